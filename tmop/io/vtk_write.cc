// tmop/io/vtk_write.cc
// Writing VTK legacy UNSTRUCTURED_GRID (.vtk): version 3.0 with the old CELLS layout (readable by
// every VTK-based tool), ASCII or BINARY (big-endian), Float64 points, tags as SCALARS int arrays,
// physical names as dataset-level FIELD int arrays [tag, dim] (vtk_common.h), fields as SCALARS /
// VECTORS / FIELD. Array names with spaces are written with "%20", as VTK does. The reader is
// vtk.cc.
#include <cstdint>
#include <string>
#include <vector>

#include "tmop/io/formats.h"
#include "tmop/io/node_order.h"
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"
#include "tmop/io/vtk_common.h"

namespace tmop {
namespace io {
namespace {

std::string encode_name(const std::string& n) {
  static const char* kHex = "0123456789ABCDEF";
  std::string out;
  for (char ch : n) {
    const unsigned char c = static_cast<unsigned char>(ch);
    if (c <= 32 || c >= 127 || c == '%' || c == '"') {
      out.push_back('%');
      out.push_back(kHex[c >> 4]);
      out.push_back(kHex[c & 15]);
    } else {
      out.push_back(ch);
    }
  }
  return out;
}

class VtkWriter {
 public:
  VtkWriter(const Mesh& mesh, bool binary, std::string* out)
      : mesh_(mesh), bin_(binary), out_(out) {}

  void write() {
    const int n = mesh_.num_vertices();
    const int m = mesh_.num_cells();
    out_->append("# vtk DataFile Version 3.0\ntmop mesh\n");
    out_->append(bin_ ? "BINARY\n" : "ASCII\n");
    out_->append("DATASET UNSTRUCTURED_GRID\n");
    write_names();
    out_->append("POINTS ");
    append_int(out_, n);
    out_->append(" double\n");
    for (int v = 0; v < n; ++v) {
      for (int j = 0; j < 3; ++j) real(coord(mesh_, v, j), j == 2 ? '\n' : ' ');
    }
    end_binary();
    std::int64_t size = 0;
    for (int c = 0; c < m; ++c) size += 1 + mesh_.cell_size(c);
    out_->append("CELLS ");
    append_int(out_, m);
    out_->push_back(' ');
    append_int(out_, size);
    out_->push_back('\n');
    for (int c = 0; c < m; ++c) {
      const CellType t = mesh_.cell_types[c];
      const int nn = cell_num_nodes(t);
      const int* p = gmsh_index_of_vtk_node(t);
      integer(nn, ' ');
      for (int i = 0; i < nn; ++i) integer(mesh_.cell(c)[p[i]], i + 1 == nn ? '\n' : ' ');
    }
    end_binary();
    out_->append("CELL_TYPES ");
    append_int(out_, m);
    out_->push_back('\n');
    for (int c = 0; c < m; ++c) integer(vtk_cell_type(mesh_.cell_types[c]), '\n');
    end_binary();
    out_->append("CELL_DATA ");
    append_int(out_, m);
    out_->push_back('\n');
    write_int_array(kRegionArray, mesh_.cell_region);
    write_int_array(kEntityArray, mesh_.cell_entity);
    for (const DataArray& a : mesh_.cell_data)
      if (!is_tag_array(a.name)) write_array(a, m);
    if (!mesh_.point_data.empty()) {
      out_->append("POINT_DATA ");
      append_int(out_, n);
      out_->push_back('\n');
      for (const DataArray& a : mesh_.point_data) write_array(a, n);
    }
  }

 private:
  void real(double v, char sep) {
    if (bin_) {
      append_binary<double>(out_, v, true);
    } else {
      append_double(out_, v);
      out_->push_back(sep);
    }
  }
  void integer(std::int64_t v, char sep) {
    if (bin_) {
      append_binary<std::int32_t>(out_, static_cast<std::int32_t>(v), true);
    } else {
      append_int(out_, v);
      out_->push_back(sep);
    }
  }
  void end_binary() {
    if (bin_) out_->push_back('\n');
  }

  // Physical names as dataset-level field data: one int array [tag, dim] per name.
  void write_names() {
    const std::vector<DataArray> field = field_data_of_names(mesh_);
    if (field.empty()) return;
    out_->append("FIELD FieldData " + std::to_string(field.size()) + "\n");
    for (const DataArray& a : field) {
      out_->append(encode_name(a.name) + " 1 2 int\n");
      for (double v : a.values) integer(static_cast<std::int64_t>(v), '\n');
      end_binary();
    }
  }

  void write_int_array(const char* name, const std::vector<std::int32_t>& values) {
    out_->append("SCALARS ");
    out_->append(name);
    out_->append(" int 1\nLOOKUP_TABLE default\n");
    for (std::int32_t v : values) integer(v, '\n');
    end_binary();
  }

  void write_array(const DataArray& a, int items) {
    if (a.components < 1 || a.values.size() != static_cast<std::size_t>(items) * a.components)
      throw Error("cannot write: data array '" + printable(a.name) + "' has " +
                  std::to_string(a.values.size()) + " values for " + std::to_string(items) +
                  " items");
    const std::string name = encode_name(a.name);
    if (a.components == 3) {
      out_->append("VECTORS " + name + " double\n");
    } else if (a.components <= 4) {
      out_->append("SCALARS " + name + " double " + std::to_string(a.components) +
                   "\nLOOKUP_TABLE default\n");
    } else {
      out_->append("FIELD FieldData 1\n" + name + " " + std::to_string(a.components) + " " +
                   std::to_string(items) + " double\n");
    }
    for (std::size_t i = 0; i < a.values.size(); ++i)
      real(a.values[i], (i + 1) % a.components == 0 ? '\n' : ' ');
    end_binary();
  }

  const Mesh& mesh_;
  bool bin_;
  std::string* out_;
};

}  // namespace

void check_vtk_writable(const Mesh& mesh) {
  check_vtk_cell_types(mesh, ".vtk");
  // "SCALARS  double 1" reads "double" as the name: an unnamed array has no legacy form.
  for (const auto* arrays : {&mesh.point_data, &mesh.cell_data})
    for (const DataArray& a : *arrays)
      if (a.name.empty())
        throw Error(std::string("cannot write an unnamed ") +
                    (arrays == &mesh.point_data ? "point" : "cell") +
                    "-data array to .vtk (legacy VTK arrays need a name; .vtu takes it)");
}

void write_vtk(const Mesh& mesh, const WriteOptions& options, std::string* out) {
  check_vtk_writable(mesh);
  for (int c = 0; c < mesh.num_cells(); ++c)
    for (int k = 0; k < mesh.cell_size(c); ++k)
      if (mesh.cell(c)[k] < 0 || mesh.cell(c)[k] >= mesh.num_vertices())
        throw Error("cannot write: cell " + std::to_string(c) + " refers to a missing vertex");
  VtkWriter(mesh, options.binary, out).write();
}

}  // namespace io
}  // namespace tmop
