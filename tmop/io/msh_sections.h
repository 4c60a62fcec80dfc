// tmop/io/msh_sections.h
// Internal to io/ (msh.cc, msh_sections.cc): the values of a .msh file in its encoding, and the
// sections beyond nodes and elements that tmop keeps: $PhysicalNames (always ASCII, in binary
// files too) and $Periodic (2.2: ASCII in binary files as well, as Gmsh writes it; 4.1: in the
// file's encoding, int entity tags and size_t counts and node tags).
#ifndef TMOP_IO_MSH_SECTIONS_H_
#define TMOP_IO_MSH_SECTIONS_H_

#include <cmath>
#include <cstdint>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "tmop/io/node_map.h"
#include "tmop/io/scanner.h"
#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

// Reads values as text tokens or as binary int32 / uint64 / double; `what` names the value in
// the located error message.
class MshValues {
 public:
  MshValues(Scanner* s, bool binary) : s_(*s), binary_(binary) {}
  bool binary() const { return binary_; }
  void set_binary(bool binary) { binary_ = binary; }
  std::int64_t get_int(std::int64_t lo, std::int64_t hi, const char* what);
  std::int64_t get_size(std::int64_t lo, std::int64_t hi, const char* what);
  double get_real(const char* what);
  // Fails unless n items of ascii_bytes (text) / binary_bytes (binary) fit in the rest.
  void check_count(std::int64_t n, std::size_t ascii_bytes, std::size_t binary_bytes,
                   const char* what);
  [[noreturn]] void fail_at(std::size_t pos, const std::string& what) const {
    binary_ ? s_.fail_byte(pos, what) : s_.fail_at(pos, what);
  }

 private:
  Scanner& s_;
  bool binary_;
};

// Appends values as text (followed by a separator) or as raw little-endian binary.
class MshEmitter {
 public:
  MshEmitter(std::string* out, bool binary) : out_(out), bin_(binary) {}
  void sz(std::uint64_t v);
  void i32(std::int64_t v);
  void real(double v);
  void end_line();  // text: the last separator becomes '\n'
  std::string* out() { return out_; }
  bool binary() const { return bin_; }

 private:
  std::string* out_;
  bool bin_;
};

// Inline: these run once per value of the largest sections.
inline std::int64_t MshValues::get_int(std::int64_t lo, std::int64_t hi, const char* what) {
  if (!binary_) return s_.integer(lo, hi, what);
  const std::size_t p = s_.pos();
  const std::int64_t v = s_.binary<std::int32_t>(false, what);
  if (v < lo || v > hi)
    s_.fail_byte(p, std::string(what) + " " + std::to_string(v) + " out of range " +
                        std::to_string(lo) + ".." + std::to_string(hi));
  return v;
}

inline std::int64_t MshValues::get_size(std::int64_t lo, std::int64_t hi, const char* what) {
  if (!binary_) return s_.integer(lo, hi, what);
  const std::size_t p = s_.pos();
  const std::uint64_t v = s_.binary<std::uint64_t>(false, what);
  if (v < static_cast<std::uint64_t>(lo) || v > static_cast<std::uint64_t>(hi))
    s_.fail_byte(p, std::string(what) + " " + std::to_string(v) + " out of range " +
                        std::to_string(lo) + ".." + std::to_string(hi));
  return static_cast<std::int64_t>(v);
}

inline double MshValues::get_real(const char* what) {
  if (!binary_) return s_.real(what);
  const std::size_t p = s_.pos();
  const double v = s_.binary<double>(false, what);
  if (!std::isfinite(v)) s_.fail_byte(p, std::string(what) + " is not finite");
  return v;
}

inline void MshValues::check_count(std::int64_t n, std::size_t ascii_bytes,
                                   std::size_t binary_bytes, const char* what) {
  if (binary_)
    s_.check_count_binary(static_cast<std::uint64_t>(n), binary_bytes, what);
  else
    s_.check_count(static_cast<std::uint64_t>(n), ascii_bytes, what);
}

// An entity written to 4.1's $Entities (one physical tag or none).
struct MshEntity {
  int dim;
  int tag;
  std::int32_t region;
  double lo[3], hi[3];
};

// After the "$PhysicalNames" token: reads through $EndPhysicalNames into mesh->physical_names.
// A name is the text between the first two double quotes of its line (Gmsh's rule: names may
// hold spaces, never a double quote); a missing quote or text after the closing one fails with
// FILE:LINE.
void read_physical_names(Scanner* s, Mesh* mesh);
// After the "$Periodic" token (nodes already read; map: node tag -> vertex).
void read_periodic(Scanner* s, bool binary, bool v4, const NodeMap& map, Mesh* mesh);

// 4.1's $PartitionedEntities (gmsh -part N, with or without -part_split): the pieces the
// partitioner cut the model's entities into. Each partitioned entity (dim, tag) names its model
// entity (parent dim, parent tag) and its physical tags; pieces of a model entity get its
// physical and its tag back (Mesh::cell_entity), so a partitioned mesh reads as the model's
// mesh. Entities the partitioner made for the cuts (parent of a higher dimension: partition
// interfaces, whose cells the model has not) and ghost entities (copies of a neighbouring
// partition's cells, -part_ghosts) are marked `skip`: their cells are not read.
struct PartitionedEntity {
  std::int32_t physical = 0;  // the first physical tag, 0 when none
  std::int32_t parent = 0;    // the model entity's tag
  bool skip = false;
};
struct PartitionedEntities {
  int partitions = 0;
  std::map<std::pair<int, int>, PartitionedEntity> entity;  // (dim, tag)
};
// After the "$PartitionedEntities" token: reads through $EndPartitionedEntities.
void read_partitioned_entities(Scanner* s, bool binary, PartitionedEntities* out);

// Throws Error("cannot write ...") for a physical name Gmsh cannot read back (a double quote or
// a line break in it).
void check_msh_names_writable(const Mesh& mesh);
void write_physical_names(const Mesh& mesh, std::string* out);
// Vertices are written as tags 1..N (vertex + 1); entity tags as stored in the links.
void write_periodic(const Mesh& mesh, int version, MshEmitter* e);
// Adds to *entities an empty entity for each (dim, tag) a periodic link names that has no cells
// (Gmsh links point and curve entities of a 2D mesh), its box that of the link's vertices.
void add_periodic_entities(const Mesh& mesh, std::vector<MshEntity>* entities);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_MSH_SECTIONS_H_
