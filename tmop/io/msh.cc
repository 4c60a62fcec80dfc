// tmop/io/msh.cc
// Gmsh .msh 2.2 and 4.1, ASCII and binary: the reader; the writer is msh_write.cc (reference: the
// "MSH file format" chapter of the Gmsh manual). Node order is Gmsh's, so cells are copied as they
// are.
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

}  // namespace

void read_msh(const std::string& path, const std::string& data, Mesh* mesh) {
  mesh->space_dim = 3;
  MshReader(path, data, mesh).read();
}

}  // namespace io
}  // namespace tmop
