// tmop/io/pvtu.cc
// .pvtu: VTK's parallel XML UnstructuredGrid, written only (mesh_io.h). The index names pieces
// STEM_K.vtu next to it; piece K is the .vtu of the cells [K n / P, (K + 1) n / P) in cell
// order, with the vertices they use (renumbered in increasing order) and the point and cell data
// of those vertices and cells. The index's PPointData / PCellData / PPoints declare exactly the
// arrays the piece writer puts in a piece (read off piece 0's XML), so the two cannot disagree.
#include <algorithm>
#include <string>
#include <vector>

#include "tmop/core/status.h"
#include "tmop/io/formats.h"
#include "tmop/io/mesh_io.h"

namespace tmop {
namespace io {

std::string pvtu_piece_path(const std::string& pvtu, int piece) {
  const std::size_t dot = pvtu.find_last_of('.');
  return pvtu.substr(0, dot) + "_" + std::to_string(piece) + ".vtu";
}

Mesh pvtu_piece(const Mesh& mesh, int piece, int pieces) {
  const std::int64_t n = mesh.num_cells();
  const int first = static_cast<int>(n * piece / pieces);
  const int end = static_cast<int>(n * (piece + 1) / pieces);
  std::vector<int> local(mesh.num_vertices(), -1);
  for (int c = first; c < end; ++c)
    for (int i = 0; i < mesh.cell_size(c); ++i) local[mesh.cell(c)[i]] = 0;
  Mesh out;
  out.space_dim = mesh.space_dim;
  out.plane_z = mesh.plane_z;
  out.physical_names = mesh.physical_names;
  std::vector<int> kept;
  for (int v = 0; v < mesh.num_vertices(); ++v)
    if (local[v] == 0) {
      local[v] = static_cast<int>(kept.size());
      kept.push_back(v);
      out.add_vertex(mesh.vertex(v));
    }
  for (int c = first; c < end; ++c) {
    std::int32_t nodes[kMaxCellNodes];
    for (int i = 0; i < mesh.cell_size(c); ++i) nodes[i] = local[mesh.cell(c)[i]];
    out.add_cell(mesh.cell_types[c], nodes, mesh.cell_region[c], mesh.cell_entity[c]);
  }
  for (const DataArray& a : mesh.point_data) {
    DataArray b{a.name, a.components, {}};
    for (int v : kept)
      for (int k = 0; k < a.components; ++k)
        b.values.push_back(a.values[static_cast<std::size_t>(v) * a.components + k]);
    out.point_data.push_back(std::move(b));
  }
  for (const DataArray& a : mesh.cell_data) {
    DataArray b{a.name, a.components, {}};
    b.values.assign(a.values.begin() + static_cast<std::ptrdiff_t>(first) * a.components,
                    a.values.begin() + static_cast<std::ptrdiff_t>(end) * a.components);
    out.cell_data.push_back(std::move(b));
  }
  return out;
}

namespace {

// The DataArray declarations inside <SECTION>...</SECTION> of a piece, as PDataArray elements
// (the attributes kept but the format and offset, which the index has no data for).
std::string declarations(const std::string& xml, const std::string& section) {
  const std::size_t open = xml.find("<" + section + ">");
  if (open == std::string::npos) return "";
  const std::size_t close = xml.find("</" + section + ">", open);
  std::string out;
  for (std::size_t at = xml.find("<DataArray ", open); at != std::string::npos && at < close;
       at = xml.find("<DataArray ", at + 1)) {
    const std::size_t end = xml.find('>', at);
    std::string attrs = xml.substr(at + 11, end - at - 11);
    for (const char* drop : {"format=\"", "offset=\""}) {
      const std::size_t a = attrs.find(drop);
      if (a == std::string::npos) continue;
      const std::size_t b = attrs.find('"', a + std::string(drop).size());
      attrs.erase(a, b + 1 - a);
    }
    while (!attrs.empty() && (attrs.back() == ' ' || attrs.back() == '/')) attrs.pop_back();
    out += "      <PDataArray " + attrs + "/>\n";
  }
  return out;
}

// The piece's file name (no directory) as an XML attribute value.
std::string source_attribute(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  std::string out;
  for (char c : slash == std::string::npos ? path : path.substr(slash + 1)) {
    if (c == '&')
      out += "&amp;";
    else if (c == '<')
      out += "&lt;";
    else if (c == '"')
      out += "&quot;";
    else
      out += c;
  }
  return out;
}

}  // namespace

std::string pvtu_index(const std::string& pvtu, const Mesh& mesh, const WriteOptions& options,
                       int pieces) {
  std::string piece0;
  write_vtu(pvtu_piece(mesh, 0, pieces), options, &piece0);
  std::string out =
      "<?xml version=\"1.0\"?>\n<VTKFile type=\"PUnstructuredGrid\" version=\"1.0\" "
      "byte_order=\"LittleEndian\" header_type=\"UInt64\">\n  <PUnstructuredGrid "
      "GhostLevel=\"0\">\n";
  out += "    <PPointData>\n" + declarations(piece0, "PointData") + "    </PPointData>\n";
  out += "    <PCellData>\n" + declarations(piece0, "CellData") + "    </PCellData>\n";
  out += "    <PPoints>\n" + declarations(piece0, "Points") + "    </PPoints>\n";
  for (int k = 0; k < pieces; ++k)
    out += "    <Piece Source=\"" + source_attribute(pvtu_piece_path(pvtu, k)) + "\"/>\n";
  return out + "  </PUnstructuredGrid>\n</VTKFile>\n";
}

}  // namespace io
}  // namespace tmop
