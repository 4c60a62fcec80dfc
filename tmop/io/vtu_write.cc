// tmop/io/vtu_write.cc
// Writing VTK XML UnstructuredGrid (.vtu): version 1.0, LittleEndian, UInt64 headers, ascii or
// uncompressed base64 inline; points Float64, connectivity / offsets Int64, types UInt8, tags
// Int32, fields Float64, physical names as dataset-level FieldData (vtk_common.h). The reader is
// vtu.cc.
#include <cstdint>
#include <string>
#include <type_traits>
#include <vector>

#include "tmop/io/base64.h"
#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"
#include "tmop/io/vtk_common.h"

namespace tmop {
namespace io {
namespace {

std::string escape(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '>')
      out += "&gt;";
    else if (c == '"')
      out += "&quot;";
    else
      out.push_back(c);
  }
  return out;
}

class VtuWriter {
 public:
  VtuWriter(const Mesh& mesh, bool binary, std::string* out)
      : mesh_(mesh), bin_(binary), out_(out) {}

  void write() {
    const int n = mesh_.num_vertices(), m = mesh_.num_cells();
    out_->append(
        "<?xml version=\"1.0\"?>\n<VTKFile type=\"UnstructuredGrid\" version=\"1.0\" "
        "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n<UnstructuredGrid>\n");
    const std::vector<DataArray> field = field_data_of_names(mesh_);
    if (!field.empty()) {
      out_->append("<FieldData>\n");
      for (const DataArray& a : field) {
        const std::vector<std::int32_t> v(a.values.begin(), a.values.end());
        array("Int32", a.name, 1, v, static_cast<int>(v.size()));
      }
      out_->append("</FieldData>\n");
    }
    out_->append("<Piece NumberOfPoints=\"");
    append_int(out_, n);
    out_->append("\" NumberOfCells=\"");
    append_int(out_, m);
    out_->append("\">\n<Points>\n");
    std::vector<double> xyz(static_cast<std::size_t>(n) * 3);
    for (int v = 0; v < n; ++v)
      for (int j = 0; j < 3; ++j) xyz[3 * static_cast<std::size_t>(v) + j] = coord(mesh_, v, j);
    array("Float64", "", 3, xyz);
    out_->append("</Points>\n<Cells>\n");
    std::vector<std::int64_t> conn, offsets;
    std::vector<std::uint8_t> types;
    conn.reserve(mesh_.cell_nodes.size());
    for (int c = 0; c < m; ++c) {
      const CellType t = mesh_.cell_types[c];
      const int* p = gmsh_index_of_vtk_node(t);
      for (int i = 0; i < cell_num_nodes(t); ++i) conn.push_back(mesh_.cell(c)[p[i]]);
      offsets.push_back(static_cast<std::int64_t>(conn.size()));
      types.push_back(static_cast<std::uint8_t>(vtk_cell_type(t)));
    }
    array("Int64", "connectivity", 1, conn);
    array("Int64", "offsets", 1, offsets);
    array("UInt8", "types", 1, types);
    out_->append("</Cells>\n<CellData>\n");
    array("Int32", kRegionArray, 1, mesh_.cell_region);
    array("Int32", kEntityArray, 1, mesh_.cell_entity);
    for (const DataArray& a : mesh_.cell_data)
      if (!is_tag_array(a.name)) data_array(a, m);
    out_->append("</CellData>\n<PointData>\n");
    for (const DataArray& a : mesh_.point_data) data_array(a, n);
    out_->append("</PointData>\n</Piece>\n</UnstructuredGrid>\n</VTKFile>\n");
  }

 private:
  void data_array(const DataArray& a, int items) {
    if (a.components < 1 || a.values.size() != static_cast<std::size_t>(items) * a.components)
      throw Error("cannot write: data array '" + printable(a.name) + "' has " +
                  std::to_string(a.values.size()) + " values for " + std::to_string(items) +
                  " items");
    array("Float64", a.name, a.components, a.values);
  }

  // tuples >= 0: written as NumberOfTuples (field data, where VTK needs it).
  template <typename T>
  void array(const char* type, const std::string& name, int comps, const std::vector<T>& v,
             int tuples = -1) {
    out_->append("<DataArray type=\"");
    out_->append(type);
    if (!name.empty()) out_->append("\" Name=\"" + escape(name));
    if (tuples >= 0) out_->append("\" NumberOfTuples=\"" + std::to_string(tuples));
    out_->append("\" NumberOfComponents=\"" + std::to_string(comps) + "\" format=\"");
    out_->append(bin_ ? "binary\">\n" : "ascii\">\n");
    if (bin_) {
      std::string raw;
      append_binary<std::uint64_t>(&raw, v.size() * sizeof(T));
      raw.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
      base64_encode(reinterpret_cast<const unsigned char*>(raw.data()), raw.size(), out_);
      out_->push_back('\n');
    } else {
      for (std::size_t i = 0; i < v.size(); ++i) {
        if constexpr (std::is_floating_point_v<T>)
          append_double(out_, v[i]);
        else
          append_int(out_, static_cast<std::int64_t>(v[i]));
        out_->push_back((i + 1) % comps == 0 ? '\n' : ' ');
      }
    }
    out_->append("</DataArray>\n");
  }

  const Mesh& mesh_;
  bool bin_;
  std::string* out_;
};

}  // namespace

void write_vtu(const Mesh& mesh, const WriteOptions& options, std::string* out) {
  check_vtk_cell_types(mesh, ".vtu");
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      if (mesh.cell(c)[k] < 0 || mesh.cell(c)[k] >= mesh.num_vertices())
        throw Error("cannot write: cell " + std::to_string(c) + " refers to a missing vertex");
  VtuWriter(mesh, options.binary, out).write();
}

}  // namespace io
}  // namespace tmop
