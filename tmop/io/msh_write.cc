// tmop/io/msh_write.cc
// The Gmsh .msh 2.2 / 4.1 writer (ASCII and binary); the reader and the file format's notes on
// tags, entities and numbering are in msh.cc.
#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <set>
#include <utility>
#include <vector>

#include "tmop/io/formats.h"
#include "tmop/io/msh_sections.h"
#include "tmop/io/node_map.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

// MshEntity tag written for each cell, and the entity list (see the file comment).
void assign_entities(const Mesh& mesh, std::vector<int>* cell_tag,
                     std::vector<MshEntity>* entities) {
  const int n = mesh.num_cells();
  std::map<std::pair<int, int>, std::set<std::int32_t>> regions;  // (dim, entity) -> regions
  int max_tag[4] = {0, 0, 0, 0};
  for (int c = 0; c < n; ++c) {
    const int d = cell_dim(mesh.cell_types[c]);
    regions[{d, mesh.cell_entity[c]}].insert(mesh.cell_region[c]);
    max_tag[d] = std::max(max_tag[d], static_cast<int>(mesh.cell_entity[c]));
  }
  std::map<std::pair<int, std::pair<int, std::int32_t>>, int> tag_of;  // (d,(e,r)) -> written
  std::map<std::pair<int, int>, int> index_of;                         // (d, written) -> entity
  cell_tag->assign(n, 0);
  entities->clear();
  for (int c = 0; c < n; ++c) {
    const int d = cell_dim(mesh.cell_types[c]);
    const int e = mesh.cell_entity[c];
    const std::int32_t r = mesh.cell_region[c];
    auto key = std::make_pair(d, std::make_pair(e, r));
    auto it = tag_of.find(key);
    int t;
    if (it != tag_of.end()) {
      t = it->second;
    } else {
      t = (e > 0 && regions[{d, e}].size() == 1) ? e : ++max_tag[d];
      tag_of[key] = t;
    }
    (*cell_tag)[c] = t;
    auto jt = index_of.find({d, t});
    int idx;
    if (jt == index_of.end()) {
      idx = static_cast<int>(entities->size());
      index_of[{d, t}] = idx;
      MshEntity ent{d, t, r, {HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
      entities->push_back(ent);
    } else {
      idx = jt->second;
    }
    MshEntity& ent = (*entities)[idx];
    const std::int32_t* nodes = mesh.cell(c);
    for (int k = 0; k < mesh.cell_size(c); ++k)
      for (int j = 0; j < 3; ++j) {
        const double x = coord(mesh, nodes[k], j);
        ent.lo[j] = std::min(ent.lo[j], x);
        ent.hi[j] = std::max(ent.hi[j], x);
      }
  }
  std::stable_sort(entities->begin(), entities->end(), [](const MshEntity& a, const MshEntity& b) {
    return a.dim != b.dim ? a.dim < b.dim : a.tag < b.tag;
  });
}

class MshWriter {
 public:
  MshWriter(const Mesh& mesh, const WriteOptions& options, std::string* out)
      : mesh_(mesh), bin_(options.binary), out_(out), e_(out, options.binary) {}

  void write(int version) {
    for (int c = 0; c < mesh_.num_cells(); ++c)
      for (int k = 0; k < mesh_.cell_size(c); ++k)
        if (mesh_.cell(c)[k] < 0 || mesh_.cell(c)[k] >= mesh_.num_vertices())
          throw Error("cannot write: cell " + std::to_string(c) + " refers to vertex " +
                      std::to_string(mesh_.cell(c)[k]) + " out of range");
    assign_entities(mesh_, &cell_tag_, &entities_);
    add_periodic_entities(mesh_, &entities_);
    out_->append(version == 41 ? "$MeshFormat\n4.1 " : "$MeshFormat\n2.2 ");
    out_->append(bin_ ? "1 8\n" : "0 8\n");
    if (bin_) {
      append_binary<std::int32_t>(out_, 1);
      out_->append("\n");
    }
    out_->append("$EndMeshFormat\n");
    write_physical_names(mesh_, out_);
    if (version == 41) {
      write_entities();
      write_nodes4();
      write_elements4();
    } else {
      write_nodes2();
      write_elements2();
    }
    write_periodic(mesh_, version, &e_);
  }

 private:
  void sz(std::uint64_t v) { e_.sz(v); }
  void i32(std::int64_t v) { e_.i32(v); }
  void real(double v) { e_.real(v); }
  void end_line() { e_.end_line(); }

  void write_entities() {
    std::uint64_t count[4] = {0, 0, 0, 0};
    for (const MshEntity& e : entities_) ++count[e.dim];
    out_->append("$Entities\n");
    for (int d = 0; d < 4; ++d) sz(count[d]);
    end_line();
    for (const MshEntity& e : entities_) {
      i32(e.tag);
      if (e.dim == 0) {
        for (int j = 0; j < 3; ++j) real(e.lo[j]);
      } else {
        for (int j = 0; j < 3; ++j) real(e.lo[j]);
        for (int j = 0; j < 3; ++j) real(e.hi[j]);
      }
      if (e.region != 0) {
        sz(1);
        i32(e.region);
      } else {
        sz(0);
      }
      if (e.dim > 0) sz(0);
      end_line();
    }
    if (bin_) out_->append("\n");
    out_->append("$EndEntities\n");
  }

  void write_nodes4() {
    const std::uint64_t n = static_cast<std::uint64_t>(mesh_.num_vertices());
    int dim = 0, tag = 0;
    for (const MshEntity& e : entities_)  // sorted by dim: the first entity of the highest dim
      if (tag == 0 || e.dim > dim) {
        dim = e.dim;
        tag = e.tag;
      }
    out_->append("$Nodes\n");
    const bool any = n > 0;
    sz(any ? 1 : 0);
    sz(n);
    sz(any ? 1 : 0);
    sz(n);
    end_line();
    if (any) {
      i32(dim);
      i32(tag);
      i32(0);
      sz(n);
      end_line();
      for (std::uint64_t v = 0; v < n; ++v) {
        sz(v + 1);
        end_line();
      }
      for (std::uint64_t v = 0; v < n; ++v) {
        for (int j = 0; j < 3; ++j) real(coord(mesh_, static_cast<int>(v), j));
        end_line();
      }
    }
    if (bin_) out_->append("\n");
    out_->append("$EndNodes\n");
  }

  void write_elements4() {
    const int m = mesh_.num_cells();
    // Blocks are maximal runs of cells with the same (dim, entity, type): keeps mesh order.
    std::vector<int> starts;
    for (int c = 0; c < m; ++c)
      if (c == 0 || mesh_.cell_types[c] != mesh_.cell_types[c - 1] ||
          cell_tag_[c] != cell_tag_[c - 1])
        starts.push_back(c);
    starts.push_back(m);
    out_->append("$Elements\n");
    sz(starts.size() - 1);
    sz(static_cast<std::uint64_t>(m));
    sz(m > 0 ? 1 : 0);
    sz(static_cast<std::uint64_t>(m));
    end_line();
    for (std::size_t b = 0; b + 1 < starts.size(); ++b) {
      const int c0 = starts[b];
      const CellType t = mesh_.cell_types[c0];
      i32(cell_dim(t));
      i32(cell_tag_[c0]);
      i32(cell_info(t).gmsh_type);
      sz(static_cast<std::uint64_t>(starts[b + 1] - c0));
      end_line();
      for (int c = c0; c < starts[b + 1]; ++c) {
        sz(static_cast<std::uint64_t>(c) + 1);
        for (int k = 0; k < mesh_.cell_size(c); ++k) sz(mesh_.cell(c)[k] + 1);
        end_line();
      }
    }
    if (bin_) out_->append("\n");
    out_->append("$EndElements\n");
  }

  void write_nodes2() {
    const int n = mesh_.num_vertices();
    out_->append("$Nodes\n");
    append_int(out_, n);
    out_->append("\n");
    for (int v = 0; v < n; ++v) {
      i32(v + 1);
      for (int j = 0; j < 3; ++j) real(coord(mesh_, v, j));
      end_line();
    }
    if (bin_) out_->append("\n");
    out_->append("$EndNodes\n");
  }

  void write_elements2() {
    const int m = mesh_.num_cells();
    out_->append("$Elements\n");
    append_int(out_, m);
    out_->append("\n");
    int c = 0;
    while (c < m) {
      int end = c + 1;
      if (bin_) {
        while (end < m && mesh_.cell_types[end] == mesh_.cell_types[c]) ++end;
        append_binary<std::int32_t>(out_, cell_info(mesh_.cell_types[c]).gmsh_type);
        append_binary<std::int32_t>(out_, end - c);
        append_binary<std::int32_t>(out_, 2);
      }
      for (int e = c; e < end; ++e) {
        i32(e + 1);
        if (!bin_) {
          i32(cell_info(mesh_.cell_types[e]).gmsh_type);
          i32(2);
        }
        i32(mesh_.cell_region[e]);
        i32(cell_tag_[e]);
        for (int k = 0; k < mesh_.cell_size(e); ++k) i32(mesh_.cell(e)[k] + 1);
        end_line();
      }
      c = end;
    }
    if (bin_) out_->append("\n");
    out_->append("$EndElements\n");
  }

  const Mesh& mesh_;
  bool bin_;
  std::string* out_;
  MshEmitter e_;
  std::vector<int> cell_tag_;
  std::vector<MshEntity> entities_;
};

}  // namespace

void check_msh_writable(const Mesh& mesh) { check_msh_names_writable(mesh); }

void write_msh(const Mesh& mesh, const WriteOptions& options, std::string* out) {
  if (options.msh_version != 41 && options.msh_version != 22)
    throw Error("cannot write MSH version " + std::to_string(options.msh_version) +
                " (22 and 41 are supported)");
  if (mesh.cell_region.size() != mesh.cell_types.size() ||
      mesh.cell_entity.size() != mesh.cell_types.size())
    throw Error("cannot write: cell_region / cell_entity sizes differ from the cell count");
  check_msh_names_writable(mesh);
  MshWriter(mesh, options, out).write(options.msh_version);
}

}  // namespace io
}  // namespace tmop
