// tmop/io/mesh_pipe.cc
// The binary mesh stream of the isolated read (mesh_pipe.h).
#include "tmop/io/mesh_pipe.h"

#include <errno.h>
#include <poll.h>
#include <unistd.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <type_traits>

#include "tmop/core/status.h"

namespace tmop {
namespace io {
namespace {

// Mesh's fields as of this stream version; a new field changes the size: send it below too.
static_assert(sizeof(Mesh) == 2 * sizeof(double) + 10 * sizeof(std::vector<int>),
              "a field was added to tmop::Mesh: add it to the mesh stream (mesh_pipe.cc)");

constexpr char kMagic[8] = {'T', 'M', 'O', 'P', 'P', 'I', 'P', '1'};
constexpr char kEnd[4] = {'E', 'N', 'D', '1'};

bool write_all(int fd, const void* data, std::size_t n) {
  const char* p = static_cast<const char*>(data);
  while (n > 0) {
    const ssize_t w = ::write(fd, p, n);
    if (w < 0 && errno == EINTR) continue;
    if (w <= 0) return false;
    p += w;
    n -= static_cast<std::size_t>(w);
  }
  return true;
}

// Small values are gathered in a buffer; large arrays go straight from the caller's memory.
class Sender {
 public:
  explicit Sender(int fd) : fd_(fd) {}
  bool ok() const { return ok_; }
  void bytes(const void* data, std::size_t n) {
    if (!ok_) return;
    if (buf_.size() + n > kBuffer) flush();
    if (n >= kBuffer) {
      ok_ = write_all(fd_, data, n);
      return;
    }
    const char* p = static_cast<const char*>(data);
    buf_.insert(buf_.end(), p, p + n);
  }
  template <typename T>
  void value(T v) {
    static_assert(std::is_trivially_copyable<T>::value, "plain values only");
    bytes(&v, sizeof v);
  }
  template <typename T>
  void array(const std::vector<T>& v) {
    value<std::uint64_t>(v.size());
    bytes(v.data(), v.size() * sizeof(T));
  }
  void text(const std::string& s) {
    value<std::uint64_t>(s.size());
    bytes(s.data(), s.size());
  }
  bool flush() {
    if (ok_ && !buf_.empty()) ok_ = write_all(fd_, buf_.data(), buf_.size());
    buf_.clear();
    return ok_;
  }

 private:
  static constexpr std::size_t kBuffer = 1 << 16;
  int fd_;
  bool ok_ = true;
  std::vector<char> buf_;
};

void send_arrays(Sender* s, const std::vector<DataArray>& arrays) {
  s->value<std::uint64_t>(arrays.size());
  for (const DataArray& a : arrays) {
    s->text(a.name);
    s->value<std::int32_t>(a.components);
    s->array(a.values);
  }
}

class Receiver {
 public:
  Receiver(int fd, bool (*stop)()) : fd_(fd), stop_(stop) {}
  void bytes(void* data, std::size_t n) {
    char* p = static_cast<char*>(data);
    while (n > 0) {
      if (at_ == end_) fill();
      const std::size_t k = std::min(n, end_ - at_);
      std::memcpy(p, buf_ + at_, k);
      at_ += k;
      p += k;
      n -= k;
    }
  }
  template <typename T>
  T value() {
    T v;
    bytes(&v, sizeof v);
    return v;
  }
  // Grows *v as its bytes arrive, so a damaged count allocates at most 1 MiB beyond the data.
  template <typename T>
  void array(std::vector<T>* v) {
    const std::uint64_t n = value<std::uint64_t>();
    if (n > (std::uint64_t(1) << 60) / sizeof(T)) bad("an array of " + std::to_string(n));
    v->clear();
    const std::size_t step = std::max<std::size_t>(1, (std::size_t(1) << 20) / sizeof(T));
    for (std::uint64_t done = 0; done < n;) {
      const std::size_t k = static_cast<std::size_t>(std::min<std::uint64_t>(step, n - done));
      v->resize(static_cast<std::size_t>(done) + k);
      bytes(v->data() + done, k * sizeof(T));
      done += k;
    }
  }
  std::string text() {
    std::vector<char> c;
    array(&c);
    return std::string(c.begin(), c.end());
  }
  std::uint64_t count() {
    const std::uint64_t n = value<std::uint64_t>();
    if (n > (std::uint64_t(1) << 40)) bad("a count of " + std::to_string(n));
    return n;
  }
  bool at_eof() {
    if (at_ < end_) return false;
    const ssize_t r = read_some();
    end_ = static_cast<std::size_t>(r);
    at_ = 0;
    return r == 0;
  }
  [[noreturn]] static void bad(const std::string& what) { throw Error("damaged data: " + what); }

 private:
  ssize_t read_some() {
    for (;;) {
      if (stop_) {
        pollfd p = {fd_, POLLIN, 0};
        const int n = ::poll(&p, 1, 200);
        if (n == 0 && stop_()) throw Error("interrupted");
        if (n <= 0) continue;  // a timeout or EINTR: ask again
      }
      const ssize_t r = ::read(fd_, buf_, sizeof buf_);
      if (r >= 0) return r;
      if (errno != EINTR) bad(std::string("read error (") + std::strerror(errno) + ")");
    }
  }
  void fill() {
    const ssize_t r = read_some();
    if (r == 0) bad("truncated");
    at_ = 0;
    end_ = static_cast<std::size_t>(r);
  }
  int fd_;
  bool (*stop_)();
  char buf_[1 << 16];
  std::size_t at_ = 0, end_ = 0;
};

void receive_arrays(Receiver* r, std::vector<DataArray>* arrays) {
  arrays->clear();
  for (std::uint64_t i = r->count(); i > 0; --i) {  // grown as items arrive, like the arrays
    DataArray& a = arrays->emplace_back();
    a.name = r->text();
    a.components = r->value<std::int32_t>();
    r->array(&a.values);
  }
}

void receive_body(Receiver* r, Mesh* mesh) {
  mesh->space_dim = r->value<std::int32_t>();
  mesh->plane_z = r->value<double>();
  r->array(&mesh->coords);
  r->array(&mesh->cell_types);
  r->array(&mesh->cell_offsets);
  r->array(&mesh->cell_nodes);
  r->array(&mesh->cell_region);
  r->array(&mesh->cell_entity);
  receive_arrays(r, &mesh->point_data);
  receive_arrays(r, &mesh->cell_data);
  mesh->physical_names.clear();
  for (std::uint64_t i = r->count(); i > 0; --i) {
    PhysicalName& p = mesh->physical_names.emplace_back();
    p.dim = r->value<std::int32_t>();
    p.tag = r->value<std::int32_t>();
    p.name = r->text();
  }
  mesh->periodic.clear();
  std::vector<std::int32_t> pairs;
  for (std::uint64_t i = r->count(); i > 0; --i) {
    PeriodicLink& l = mesh->periodic.emplace_back();
    l.dim = r->value<std::int32_t>();
    l.tag = r->value<std::int32_t>();
    l.master_tag = r->value<std::int32_t>();
    r->array(&l.affine);
    r->array(&pairs);
    if (pairs.size() % 2 != 0) Receiver::bad("an odd periodic node list");
    l.nodes.resize(pairs.size() / 2);
    for (std::size_t i = 0; i < l.nodes.size(); ++i)
      l.nodes[i] = std::make_pair(pairs[2 * i], pairs[2 * i + 1]);
  }
}

// The stream is tmop's own, but a child that corrupted its memory may send anything: what the
// rest of tmop indexes with is checked (linear), the rest is validate_mesh's work as for any read.
void check_structure(const Mesh& m) {
  if (m.space_dim != 2 && m.space_dim != 3)
    Receiver::bad("space_dim " + std::to_string(m.space_dim));
  if (m.coords.size() % m.space_dim != 0) Receiver::bad("a partial vertex");
  const std::size_t nc = m.cell_types.size();
  if (m.cell_offsets.size() != nc + 1 || m.cell_offsets[0] != 0 ||
      m.cell_offsets[nc] != static_cast<std::int64_t>(m.cell_nodes.size()) ||
      m.cell_region.size() > nc || m.cell_entity.size() > nc)
    Receiver::bad("inconsistent cell arrays");
  for (std::size_t c = 0; c < nc; ++c) {
    if (static_cast<int>(m.cell_types[c]) >= kNumCellTypes) Receiver::bad("a bad cell type");
    if (m.cell_offsets[c + 1] - m.cell_offsets[c] != cell_num_nodes(m.cell_types[c]))
      Receiver::bad("a cell with a wrong node count");
  }
  const std::int64_t nv = static_cast<std::int64_t>(m.coords.size() / m.space_dim);
  for (std::int32_t v : m.cell_nodes)
    if (v < 0 || v >= nv) Receiver::bad("a node out of range");
}

}  // namespace

bool send_mesh(int fd, const Mesh& mesh) {
  Sender s(fd);
  s.bytes(kMagic, sizeof kMagic);
  s.value<char>('M');
  s.value<std::int32_t>(mesh.space_dim);
  s.value<double>(mesh.plane_z);
  s.array(mesh.coords);
  s.array(mesh.cell_types);
  s.array(mesh.cell_offsets);
  s.array(mesh.cell_nodes);
  s.array(mesh.cell_region);
  s.array(mesh.cell_entity);
  send_arrays(&s, mesh.point_data);
  send_arrays(&s, mesh.cell_data);
  s.value<std::uint64_t>(mesh.physical_names.size());
  for (const PhysicalName& p : mesh.physical_names) {
    s.value<std::int32_t>(p.dim);
    s.value<std::int32_t>(p.tag);
    s.text(p.name);
  }
  s.value<std::uint64_t>(mesh.periodic.size());
  for (const PeriodicLink& l : mesh.periodic) {
    s.value<std::int32_t>(l.dim);
    s.value<std::int32_t>(l.tag);
    s.value<std::int32_t>(l.master_tag);
    s.array(l.affine);
    s.value<std::uint64_t>(2 * l.nodes.size());
    for (const auto& n : l.nodes) {
      s.value<std::int32_t>(n.first);
      s.value<std::int32_t>(n.second);
    }
  }
  s.bytes(kEnd, sizeof kEnd);
  return s.flush();
}

bool send_message(int fd, char kind, const std::string& message) {
  Sender s(fd);
  s.bytes(kMagic, sizeof kMagic);
  s.value<char>(kind);
  s.text(message);
  s.bytes(kEnd, sizeof kEnd);
  return s.flush();
}

char receive_mesh(int fd, Mesh* mesh, std::string* message, bool (*stop)()) {
  Receiver r(fd, stop);
  char magic[sizeof kMagic];
  r.bytes(magic, sizeof magic);
  if (std::memcmp(magic, kMagic, sizeof kMagic) != 0) Receiver::bad("not a mesh stream");
  const char kind = r.value<char>();
  if (kind == 'M') {
    receive_body(&r, mesh);
    check_structure(*mesh);
  } else if (kind == 'E' || kind == 'A' || kind == 'X') {
    *message = r.text();
  } else {
    Receiver::bad("unknown kind " + std::to_string(static_cast<unsigned char>(kind)));
  }
  char end[sizeof kEnd];
  r.bytes(end, sizeof end);
  if (std::memcmp(end, kEnd, sizeof kEnd) != 0) Receiver::bad("no end marker");
  if (!r.at_eof()) Receiver::bad("bytes after the end marker");
  return kind;
}

}  // namespace io
}  // namespace tmop
