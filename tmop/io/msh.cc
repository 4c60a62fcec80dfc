// tmop/io/msh.cc
// Gmsh .msh 2.2 and 4.1, ASCII and binary (reference: the "MSH file format" chapter of the Gmsh
// manual). Node order is Gmsh's, so cells are copied as they are.
//
// Names and periodicity: $PhysicalNames <-> Mesh::physical_names, $Periodic <-> Mesh::periodic
// (msh_sections.cc); both are written back in either version.
//
// Tags: 2.2 elements carry (physical, elementary) as their first two tags; 4.1 elements belong to
// an entity (dim, tag) whose physical tags are listed in $Entities. Both map to
// Mesh::cell_region (the first physical tag; 0 when none) and Mesh::cell_entity. A partitioned
// file's entities ($PartitionedEntities) map to their model entities (msh_sections.h).
//
// Writing: tmop numbers nodes 1..N and elements 1..M in mesh order. 4.1 needs $Entities; we write
// one entity per (dimension, cell_entity) with its bounding box and physical tag, no boundary
// links (Gmsh accepts that). An entity tag shared by cells of different regions, and tag 0, are
// split into fresh tags (max + 1, ...) so each entity has one physical tag; the same entity tags
// are used for 2.2 so both versions read back identically. All nodes go in one block on the
// first entity of the highest dimension. Entities that only periodic links name (the point and
// curve entities Gmsh links in a 2D mesh) are written without cells.
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
#include "tmop/io/scanner.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

class MshReader {
 public:
  MshReader(const std::string& path, const std::string& data, Mesh* mesh)
      : s_(path, data), mesh_(mesh) {}

  void read() {
    if (s_.at_end()) s_.fail("empty file");
    if (s_.token() != "$MeshFormat") s_.fail("not a Gmsh file: expected $MeshFormat");
    read_format();
    bool have_nodes = false;
    std::string_view t;
    while (s_.try_token(&t)) {
      const std::size_t start = s_.pos() - t.size();
      if (t == "$Nodes") {
        if (have_nodes) s_.fail_at(start, "second $Nodes section");
        v4_ ? read_nodes4() : read_nodes2();
        have_nodes = true;
        finish_nodes();
      } else if (t == "$Elements") {
        if (!have_nodes) s_.fail_at(start, "$Elements before $Nodes");
        v4_ ? read_elements4() : read_elements2();
      } else if (t == "$Entities" && v4_) {
        read_entities();
      } else if (t == "$PartitionedEntities" && v4_) {
        read_partitioned_entities(&s_, binary_, &partitioned_);
      } else if (t == "$PhysicalNames") {
        read_physical_names(&s_, mesh_);
      } else if (t == "$Periodic") {
        if (!have_nodes) s_.fail_at(start, "$Periodic before $Nodes");
        read_periodic(&s_, binary_, v4_, map_, mesh_);
      } else if (t.size() > 1 && t[0] == '$') {
        skip_section(t, start);
      } else {
        s_.fail_at(start, "expected a $Section header, got '" + printable(t) + "'");
      }
    }
    if (!have_nodes) s_.fail("no $Nodes section");
  }

 private:
  void read_format() {
    const std::size_t vpos = s_.pos();
    const std::string_view version = s_.token();
    if (version == "4.1") {
      v4_ = true;
    } else if (version == "2.2" || version == "2.1" || version == "2" || version == "2.0") {
      v4_ = false;
    } else {
      s_.fail_at(vpos, "unsupported MSH version " + printable(version) + " (2.2 and 4.1 are)");
    }
    binary_ = s_.integer(0, 1, "file type (0 ascii, 1 binary)") == 1;
    v_.set_binary(binary_);
    const std::size_t dpos = s_.pos();
    const std::int64_t data_size = s_.integer(0, 64, "data size");
    if (binary_ && data_size != 8)
      s_.fail_at(dpos, "binary data size " + std::to_string(data_size) +
                           " unsupported (tmop reads 8-byte size_t and double)");
    if (binary_) {
      s_.skip_line();
      const std::size_t mpos = s_.pos();
      const std::int32_t one = s_.binary<std::int32_t>(false, "endianness marker");
      if (one != 1) {
        s_.fail_byte(mpos, "endianness marker is " + std::to_string(one) +
                               ", expected 1 (file written on a machine of other byte order?)");
      }
    }
    expect("$EndMeshFormat");
  }

  void expect(std::string_view what) {
    const std::size_t p = s_.pos();
    std::string_view t;
    if (!s_.try_token(&t)) s_.fail("unexpected end of file, expected " + std::string(what));
    if (t != what)
      s_.fail_at(p + (s_.pos() - p - t.size()),
                 "expected " + std::string(what) + ", got '" + printable(t) + "'");
  }

  void skip_section(std::string_view name, std::size_t start) {
    const std::string end = "$End" + std::string(name.substr(1));
    const std::size_t e = s_.data().find(end, s_.pos());
    if (e == std::string_view::npos)
      s_.fail_at(start, "section " + printable(name) + " has no " + printable(end));
    s_.set_pos(e + end.size());
  }

  // Values in the current encoding (msh_sections.h). `what` names the value for messages.
  std::int64_t get_int(std::int64_t lo, std::int64_t hi, const char* what) {
    return v_.get_int(lo, hi, what);
  }
  std::int64_t get_size(std::int64_t lo, std::int64_t hi, const char* what) {
    return v_.get_size(lo, hi, what);
  }
  double get_real(const char* what) { return v_.get_real(what); }
  // Counts are written as text in 2.2 even in binary files.
  void check_count(std::int64_t n, std::size_t ascii_bytes, std::size_t binary_bytes,
                   const char* what) {
    v_.check_count(n, ascii_bytes, binary_bytes, what);
  }

  void add_node(std::int64_t tag) {
    tags_.push_back(tag);
    for (int k = 0; k < 3; ++k) mesh_->coords.push_back(get_real("coordinate"));
  }

  void read_nodes2() {
    const std::int64_t n = s_.integer(0, kMaxInt32 - 1, "number of nodes");
    if (binary_) s_.skip_line();
    check_count(n, 8, 28, "node");
    tags_.reserve(n);
    mesh_->coords.reserve(3 * n);
    for (std::int64_t i = 0; i < n; ++i) add_node(get_int(1, kMaxInt32, "node tag"));
    expect("$EndNodes");
  }

  void read_nodes4() {
    if (binary_) s_.skip_line();
    const std::int64_t blocks = get_size(0, kMaxInt32, "number of node blocks");
    const std::int64_t n = get_size(0, kMaxInt32 - 1, "number of nodes");
    get_size(0, kMaxInt64, "min node tag");
    get_size(0, kMaxInt64, "max node tag");
    check_count(blocks, 8, 20, "node block");
    check_count(n, 8, 32, "node");
    tags_.reserve(n);
    mesh_->coords.reserve(3 * n);
    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      const int dim = static_cast<int>(get_int(0, 3, "entity dimension"));
      get_int(std::numeric_limits<std::int32_t>::min(), kMaxInt32, "entity tag");
      const bool parametric = get_int(0, 1, "parametric flag") == 1;
      const std::int64_t m = get_size(0, n - seen, "number of nodes in block");
      for (std::int64_t i = 0; i < m; ++i) tags_.push_back(get_size(1, kMaxInt64, "node tag"));
      const int extra = parametric ? dim : 0;
      for (std::int64_t i = 0; i < m; ++i) {
        for (int k = 0; k < 3; ++k) mesh_->coords.push_back(get_real("coordinate"));
        for (int k = 0; k < extra; ++k) get_real("parametric coordinate");
      }
      seen += m;
    }
    if (seen != n)
      s_.fail("node blocks hold " + std::to_string(seen) + " nodes, header says " +
              std::to_string(n));
    expect("$EndNodes");
  }

  void finish_nodes() {
    std::int64_t dup = 0;
    if (!map_.build(tags_, &dup))
      s_.fail("duplicate node tag " + std::to_string(dup) + " in $Nodes");
  }

  std::int32_t node(std::int64_t tag, std::size_t pos) {
    const std::int32_t v = map_.find(tag);
    if (v < 0) {
      const std::string msg = "node tag " + std::to_string(tag) + " is not defined in $Nodes";
      binary_ ? s_.fail_byte(pos, msg) : s_.fail_at(pos, msg);
    }
    return v;
  }

  CellType element_type(std::int64_t gmsh_type, std::size_t pos) {
    CellType t;
    if (!cell_type_from_gmsh(static_cast<int>(gmsh_type), &t)) {
      const std::string msg = "unsupported Gmsh element type " + std::to_string(gmsh_type) +
                              " (tmop reads " + supported_cell_types() + ")";
      binary_ ? s_.fail_byte(pos, msg) : s_.fail_at(pos, msg);
    }
    return t;
  }

  void read_elements2() {
    const std::int64_t m = s_.integer(0, kMaxInt32 - 1, "number of elements");
    if (binary_) s_.skip_line();
    check_count(m, 10, 16, "element");
    reserve_cells(m);
    std::int32_t nodes[kMaxCellNodes];
    std::int64_t done = 0;
    while (done < m) {
      std::int64_t follow = 1, ntags = 0;
      CellType type = CellType::kVertex;
      if (binary_) {
        const std::size_t p = s_.pos();
        type = element_type(get_int(0, kMaxInt32, "element type"), p);
        follow = get_int(1, m - done, "number of elements following");
        ntags = get_int(0, 1000, "number of tags");
        s_.check_count_binary(follow, 4 * (1 + ntags + cell_num_nodes(type)), "element");
      }
      for (std::int64_t i = 0; i < follow; ++i) {
        get_int(0, kMaxInt64, "element tag");
        if (!binary_) {
          s_.skip_space();
          const std::size_t p = s_.pos();
          type = element_type(s_.integer(0, kMaxInt32, "element type"), p);
          ntags = s_.integer(0, 1000, "number of tags");
        }
        std::int32_t phys = 0, ent = 0;
        for (std::int64_t k = 0; k < ntags; ++k) {
          const std::int64_t tag = get_int(-kMaxInt32, kMaxInt32, "element tag value");
          if (k == 0) phys = static_cast<std::int32_t>(tag);
          if (k == 1) ent = static_cast<std::int32_t>(tag);
        }
        const int nn = cell_num_nodes(type);
        for (int k = 0; k < nn; ++k) {
          if (!binary_) s_.skip_space();
          const std::size_t p = s_.pos();
          nodes[k] = node(get_int(1, kMaxInt64, "node tag"), p);
        }
        mesh_->add_cell(type, nodes, phys, ent);
      }
      done += follow;
    }
    expect("$EndElements");
  }

  void read_entities() {
    if (binary_) s_.skip_line();
    std::int64_t count[4];
    for (int d = 0; d < 4; ++d) count[d] = get_size(0, kMaxInt32, "number of entities");
    for (int d = 0; d < 4; ++d) {
      check_count(count[d], 8, 20, "entity");
      for (std::int64_t i = 0; i < count[d]; ++i) {
        const std::int64_t tag = get_int(-kMaxInt32, kMaxInt32, "entity tag");
        for (int k = 0; k < (d == 0 ? 3 : 6); ++k) get_real("entity bounding box");
        const std::int64_t nphys = get_size(0, kMaxInt32, "number of physical tags");
        check_count(nphys, 2, 4, "physical tag");
        std::int32_t phys = 0;
        for (std::int64_t k = 0; k < nphys; ++k) {
          const std::int64_t p = get_int(-kMaxInt32, kMaxInt32, "physical tag");
          if (k == 0) phys = static_cast<std::int32_t>(p);
        }
        physical_[{d, static_cast<int>(tag)}] = phys;
        if (d > 0) {
          const std::int64_t nb = get_size(0, kMaxInt32, "number of bounding entities");
          check_count(nb, 2, 4, "bounding entity");
          for (std::int64_t k = 0; k < nb; ++k)
            get_int(-kMaxInt32, kMaxInt32, "bounding entity tag");
        }
      }
    }
    expect("$EndEntities");
  }

  void read_elements4() {
    if (binary_) s_.skip_line();
    const std::int64_t blocks = get_size(0, kMaxInt32, "number of element blocks");
    const std::int64_t m = get_size(0, kMaxInt32 - 1, "number of elements");
    get_size(0, kMaxInt64, "min element tag");
    get_size(0, kMaxInt64, "max element tag");
    check_count(blocks, 8, 20, "element block");
    check_count(m, 4, 16, "element");
    reserve_cells(m);
    std::int32_t nodes[kMaxCellNodes];
    std::int64_t seen = 0;
    for (std::int64_t b = 0; b < blocks; ++b) {
      if (!binary_) s_.skip_space();
      const std::size_t bpos = s_.pos();
      const int dim = static_cast<int>(get_int(0, 3, "entity dimension"));
      const int tag = static_cast<int>(get_int(-kMaxInt32, kMaxInt32, "entity tag"));
      if (!binary_) s_.skip_space();
      const std::size_t tpos = s_.pos();
      const CellType type = element_type(get_int(0, kMaxInt32, "element type"), tpos);
      if (cell_dim(type) != dim) {
        const std::string msg = std::string("element type ") + cell_name(type) + " (dimension " +
                                std::to_string(cell_dim(type)) + ") in an entity of dimension " +
                                std::to_string(dim);
        binary_ ? s_.fail_byte(bpos, msg) : s_.fail_at(bpos, msg);
      }
      const std::int64_t count = get_size(0, m - seen, "number of elements in block");
      const int nn = cell_num_nodes(type);
      check_count(count, 2 * (1 + nn), 8 * (1 + nn), "element");
      auto it = physical_.find({dim, tag});
      std::int32_t phys = it == physical_.end() ? 0 : it->second, entity = tag;
      bool skip = false;  // a partition's cut or ghost cells (msh_sections.h)
      if (auto pe = partitioned_.entity.find({dim, tag}); pe != partitioned_.entity.end()) {
        phys = pe->second.physical;
        entity = pe->second.parent;
        skip = pe->second.skip;
      }
      for (std::int64_t i = 0; i < count; ++i) {
        get_size(0, kMaxInt64, "element tag");
        for (int k = 0; k < nn; ++k) {
          if (!binary_) s_.skip_space();
          const std::size_t p = s_.pos();
          const std::int64_t node_tag = get_size(1, kMaxInt64, "node tag");
          if (!skip) nodes[k] = node(node_tag, p);
        }
        if (!skip) mesh_->add_cell(type, nodes, phys, entity);
      }
      seen += count;
    }
    if (seen != m)
      s_.fail("element blocks hold " + std::to_string(seen) + " elements, header says " +
              std::to_string(m));
    expect("$EndElements");
  }

  void reserve_cells(std::int64_t m) {
    mesh_->cell_types.reserve(mesh_->cell_types.size() + m);
    mesh_->cell_offsets.reserve(mesh_->cell_offsets.size() + m);
    mesh_->cell_region.reserve(mesh_->cell_region.size() + m);
    mesh_->cell_entity.reserve(mesh_->cell_entity.size() + m);
    mesh_->cell_nodes.reserve(mesh_->cell_nodes.size() + 4 * m);
  }

  Scanner s_;
  Mesh* mesh_;
  bool v4_ = false;
  bool binary_ = false;
  MshValues v_{&s_, false};
  std::vector<std::int64_t> tags_;
  NodeMap map_;
  std::map<std::pair<int, int>, std::int32_t> physical_;
  PartitionedEntities partitioned_;
};

// ---- writing ------------------------------------------------------------------------------

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

void read_msh(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  MshReader(path, data, mesh).read();
}

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
