// tmop/io/msh_sections.cc
// $PhysicalNames and $Periodic of Gmsh .msh files (the "MSH file format" chapter of the Gmsh
// manual, 4.1 and the legacy 2.2 layout), and the value encoding shared with msh.cc.
#include "tmop/io/msh_sections.h"

#include <algorithm>
#include <cmath>
#include <limits>

#include "tmop/io/formats.h"
#include "tmop/io/text_format.h"

namespace tmop {
namespace io {
namespace {

constexpr std::int64_t kMaxInt32 = std::numeric_limits<std::int32_t>::max();
constexpr std::int64_t kMaxInt64 = std::numeric_limits<std::int64_t>::max();

void expect_end(Scanner* s, std::string_view what) {
  std::string_view t;
  if (!s->try_token(&t)) s->fail("unexpected end of file, expected " + std::string(what));
  if (t != what)
    s->fail_at(s->pos() - t.size(),
               "expected " + std::string(what) + ", got '" + printable(t) + "'");
}

bool only_space(std::string_view s) {
  for (char c : s)
    if (!is_space(c)) return false;
  return true;
}

}  // namespace

void MshEmitter::sz(std::uint64_t v) {
  if (bin_) return append_binary<std::uint64_t>(out_, v);
  append_int(out_, static_cast<std::int64_t>(v));
  out_->push_back(' ');
}

void MshEmitter::i32(std::int64_t v) {
  if (bin_) return append_binary<std::int32_t>(out_, static_cast<std::int32_t>(v));
  append_int(out_, v);
  out_->push_back(' ');
}

void MshEmitter::real(double v) {
  if (bin_) return append_binary<double>(out_, v);
  append_double(out_, v);
  out_->push_back(' ');
}

void MshEmitter::end_line() {
  if (!bin_ && !out_->empty() && out_->back() == ' ') out_->back() = '\n';
}

void read_physical_names(Scanner* s, Mesh* mesh) {
  const std::int64_t n = s->integer(0, kMaxInt32, "number of physical names");
  s->check_count(static_cast<std::uint64_t>(n), 7, "physical name");  // `0 1 ""` and a newline
  for (std::int64_t i = 0; i < n; ++i) {
    s->skip_space();
    const std::size_t p = s->pos();
    const int dim = static_cast<int>(s->integer(0, 3, "physical dimension"));
    const int tag = static_cast<int>(s->integer(-kMaxInt32, kMaxInt32, "physical tag"));
    const std::string_view rest = s->line();
    const std::size_t q0 = rest.find('"');
    if (q0 == std::string_view::npos || !only_space(rest.substr(0, q0)))
      s->fail_at(p, "expected a physical name in double quotes after the tag");
    const std::size_t q1 = rest.find('"', q0 + 1);
    if (q1 == std::string_view::npos)
      s->fail_at(p, "physical name has no closing double quote on its line");
    if (!only_space(rest.substr(q1 + 1)))
      s->fail_at(p, "text after the closing quote of a physical name (names cannot hold '\"')");
    if (mesh->physical_name(dim, tag))
      s->fail_at(p, "second name for physical tag " + std::to_string(tag) + " of dimension " +
                        std::to_string(dim));
    mesh->set_physical_name(dim, tag, std::string(rest.substr(q0 + 1, q1 - q0 - 1)));
  }
  expect_end(s, "$EndPhysicalNames");
}

void read_periodic(Scanner* s, bool binary, bool v4, const NodeMap& map, Mesh* mesh) {
  MshValues v(s, binary && v4);  // 2.2 writes $Periodic as text in binary files too
  if (v.binary()) s->skip_line();
  const std::int64_t n = v.get_size(0, kMaxInt32, "number of periodic links");
  v.check_count(n, 8, 12 + 16, "periodic link");
  auto vertex = [&](const char* what) {
    if (!v.binary()) s->skip_space();
    const std::size_t p = s->pos();
    const std::int64_t tag = v.get_size(1, kMaxInt64, what);
    const std::int32_t x = map.find(tag);
    if (x < 0) v.fail_at(p, std::string(what) + " " + std::to_string(tag) + " is not in $Nodes");
    return x;
  };
  for (std::int64_t i = 0; i < n; ++i) {
    PeriodicLink link;
    link.dim = static_cast<int>(v.get_int(0, 3, "periodic entity dimension"));
    link.tag = static_cast<int>(v.get_int(-kMaxInt32, kMaxInt32, "periodic entity tag"));
    link.master_tag = static_cast<int>(v.get_int(-kMaxInt32, kMaxInt32, "master entity tag"));
    std::int64_t affine = 0;
    if (v4) {
      if (!v.binary()) s->skip_space();
      const std::size_t p = s->pos();
      affine = v.get_size(0, 16, "number of affine values");
      if (affine != 0 && affine != 16)
        v.fail_at(p, "a periodic link has 0 or 16 affine values, not " + std::to_string(affine));
    } else {
      const std::size_t p = s->pos();
      std::string_view t;
      if (s->try_token(&t) && t == "Affine")
        affine = 16;
      else
        s->set_pos(p);
    }
    for (std::int64_t k = 0; k < affine; ++k) link.affine.push_back(v.get_real("affine value"));
    const std::int64_t m = v.get_size(0, kMaxInt32, "number of periodic nodes");
    v.check_count(m, 4, 16, "periodic node pair");
    link.nodes.reserve(static_cast<std::size_t>(m));
    for (std::int64_t k = 0; k < m; ++k) {
      const std::int32_t a = vertex("periodic node tag");
      link.nodes.emplace_back(a, vertex("master node tag"));
    }
    mesh->periodic.push_back(std::move(link));
  }
  expect_end(s, "$EndPeriodic");
}

void read_partitioned_entities(Scanner* s, bool binary, PartitionedEntities* out) {
  MshValues v(s, binary);
  if (v.binary()) s->skip_line();
  *out = PartitionedEntities();
  out->partitions = static_cast<int>(v.get_size(0, kMaxInt32, "number of partitions"));
  const std::int64_t ghosts = v.get_size(0, kMaxInt32, "number of ghost entities");
  v.check_count(ghosts, 4, 8, "ghost entity");
  std::vector<int> ghost_tags;
  for (std::int64_t i = 0; i < ghosts; ++i) {
    ghost_tags.push_back(static_cast<int>(v.get_int(-kMaxInt32, kMaxInt32, "ghost entity tag")));
    v.get_int(-kMaxInt32, kMaxInt32, "ghost entity partition");
  }
  std::int64_t count[4];
  for (int d = 0; d < 4; ++d) count[d] = v.get_size(0, kMaxInt32, "number of entities");
  int top = 0;  // ghost entities are of the highest dimension that has entities
  for (int d = 0; d < 4; ++d) {
    v.check_count(count[d], 12, 28, "partitioned entity");
    if (count[d] > 0) top = d;
    for (std::int64_t i = 0; i < count[d]; ++i) {
      const int tag = static_cast<int>(v.get_int(-kMaxInt32, kMaxInt32, "entity tag"));
      const int parent_dim = static_cast<int>(v.get_int(0, 3, "parent dimension"));
      const int parent = static_cast<int>(v.get_int(-kMaxInt32, kMaxInt32, "parent tag"));
      const std::int64_t parts = v.get_size(0, kMaxInt32, "number of partitions of the entity");
      v.check_count(parts, 2, 4, "partition tag");
      for (std::int64_t k = 0; k < parts; ++k) v.get_int(-kMaxInt32, kMaxInt32, "partition tag");
      for (int k = 0; k < (d == 0 ? 3 : 6); ++k) v.get_real("entity bounding box");
      const std::int64_t nphys = v.get_size(0, kMaxInt32, "number of physical tags");
      v.check_count(nphys, 2, 4, "physical tag");
      PartitionedEntity e;
      for (std::int64_t k = 0; k < nphys; ++k) {
        const std::int64_t phys = v.get_int(-kMaxInt32, kMaxInt32, "physical tag");
        if (k == 0) e.physical = static_cast<std::int32_t>(phys);
      }
      if (d > 0) {
        const std::int64_t nb = v.get_size(0, kMaxInt32, "number of bounding entities");
        v.check_count(nb, 2, 4, "bounding entity");
        for (std::int64_t k = 0; k < nb; ++k)
          v.get_int(-kMaxInt32, kMaxInt32, "bounding entity tag");
      }
      e.parent = parent_dim == d ? parent : tag;
      e.skip = parent_dim != d;
      out->entity[{d, tag}] = e;
    }
  }
  for (int tag : ghost_tags) out->entity[{top, tag}].skip = true;
  expect_end(s, "$EndPartitionedEntities");
}

void check_msh_names_writable(const Mesh& mesh) {
  for (const PhysicalName& p : mesh.physical_names)
    if (p.name.find_first_of("\"\n\r") != std::string::npos)
      throw Error("cannot write physical name '" + printable(p.name) +
                  "' to .msh (Gmsh names cannot hold a double quote or a line break)");
}

void write_physical_names(const Mesh& mesh, std::string* out) {
  if (mesh.physical_names.empty()) return;
  std::vector<PhysicalName> names = mesh.physical_names;
  std::stable_sort(names.begin(), names.end(), [](const PhysicalName& a, const PhysicalName& b) {
    return a.dim != b.dim ? a.dim < b.dim : a.tag < b.tag;
  });
  out->append("$PhysicalNames\n");
  append_int(out, static_cast<std::int64_t>(names.size()));
  out->push_back('\n');
  for (const PhysicalName& p : names) {
    append_int(out, p.dim);
    out->push_back(' ');
    append_int(out, p.tag);
    out->append(" \"" + p.name + "\"\n");
  }
  out->append("$EndPhysicalNames\n");
}

void write_periodic(const Mesh& mesh, int version, MshEmitter* e) {
  if (mesh.periodic.empty()) return;
  for (const PeriodicLink& l : mesh.periodic) {
    if (!l.affine.empty() && l.affine.size() != 16)
      throw Error("cannot write a periodic link with " + std::to_string(l.affine.size()) +
                  " affine values (0 or 16)");
    for (const auto& p : l.nodes)
      if (p.first < 0 || p.first >= mesh.num_vertices() || p.second < 0 ||
          p.second >= mesh.num_vertices())
        throw Error("cannot write: a periodic link refers to a vertex out of range");
  }
  MshEmitter text(e->out(), false);
  MshEmitter& w = version == 41 ? *e : text;  // 2.2: text, as Gmsh writes it
  std::string* out = e->out();
  out->append("$Periodic\n");
  w.sz(mesh.periodic.size());
  w.end_line();
  for (const PeriodicLink& l : mesh.periodic) {
    w.i32(l.dim);
    w.i32(l.tag);
    w.i32(l.master_tag);
    w.end_line();
    if (version == 41) {
      w.sz(l.affine.size());
    } else if (!l.affine.empty()) {
      out->append("Affine ");
    }
    for (double a : l.affine) w.real(a);
    if (version == 41 || !l.affine.empty()) w.end_line();
    w.sz(l.nodes.size());
    w.end_line();
    for (const auto& p : l.nodes) {
      w.sz(static_cast<std::uint64_t>(p.first) + 1);
      w.sz(static_cast<std::uint64_t>(p.second) + 1);
      w.end_line();
    }
  }
  if (w.binary()) out->append("\n");
  out->append("$EndPeriodic\n");
}

void add_periodic_entities(const Mesh& mesh, std::vector<MshEntity>* entities) {
  auto add = [&](int dim, int tag, const PeriodicLink& l, bool master) {
    for (const MshEntity& e : *entities)
      if (e.dim == dim && e.tag == tag) return;
    MshEntity e{dim, tag, 0, {HUGE_VAL, HUGE_VAL, HUGE_VAL}, {-HUGE_VAL, -HUGE_VAL, -HUGE_VAL}};
    for (const auto& p : l.nodes)
      for (int j = 0; j < 3; ++j) {
        const double x = coord(mesh, master ? p.second : p.first, j);
        e.lo[j] = std::min(e.lo[j], x);
        e.hi[j] = std::max(e.hi[j], x);
      }
    if (l.nodes.empty()) e.lo[0] = e.lo[1] = e.lo[2] = e.hi[0] = e.hi[1] = e.hi[2] = 0;
    entities->push_back(e);
  };
  for (const PeriodicLink& l : mesh.periodic) {
    add(l.dim, l.tag, l, false);
    add(l.dim, l.master_tag, l, true);
  }
  std::stable_sort(entities->begin(), entities->end(), [](const MshEntity& a, const MshEntity& b) {
    return a.dim != b.dim ? a.dim < b.dim : a.tag < b.tag;
  });
}

}  // namespace io
}  // namespace tmop
