// tmop/io/netcdf_header.cc
// The netCDF classic header (netcdf_header.h). Layout, big-endian (the NetCDF Classic Format
// Specification; N = 4 bytes in CDF-1/2, 8 in CDF-5; OFFSET = 4 bytes in CDF-1, 8 otherwise):
//   'C' 'D' 'F' VERSION, numrecs (N), dim_list, gatt_list, var_list
//   list    = ABSENT (tag 0, count 0) | tag (4 bytes: 0x0A dims, 0x0C attributes, 0x0B vars) count
//   name    = count (N) bytes, padded to 4
//   dim     = name length (N)
//   attr    = name nc_type (4) count (N) values (padded to 4)
//   var     = name ndims (N) dimid (N) x ndims, att_list, nc_type (4), vsize (N), begin (OFFSET)
#include "tmop/io/netcdf_header.h"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <limits>
#include <set>

#include "tmop/core/status.h"
#include "tmop/io/scanner.h"  // printable

namespace tmop {
namespace io {
namespace {

constexpr std::uint64_t kMaxName = 256;      // NC_MAX_NAME
constexpr std::uint64_t kMaxVarDims = 1024;  // NC_MAX_VAR_DIMS
constexpr std::uint32_t kTagDim = 0x0A, kTagVar = 0x0B, kTagAttr = 0x0C;

std::uint64_t type_size(int type) {
  switch (type) {
    case kNcByte:
    case kNcChar:
    case kNcUbyte:
      return 1;
    case kNcShort:
    case kNcUshort:
      return 2;
    case kNcInt:
    case kNcFloat:
    case kNcUint:
      return 4;
    case kNcDouble:
    case kNcInt64:
    case kNcUint64:
      return 8;
    default:
      return 0;
  }
}

// A name from the file in a message: quoted, control bytes escaped (io::printable).
std::string q(const std::string& name) { return "'" + printable(name) + "'"; }

std::uint64_t pad4(std::uint64_t n) { return n + (4 - n % 4) % 4; }

// a * b, or false when it exceeds limit.
bool mul(std::uint64_t a, std::uint64_t b, std::uint64_t limit, std::uint64_t* out) {
  if (a != 0 && b > limit / a) return false;
  *out = a * b;
  return *out <= limit;
}

// Reads the header front to back; every read is bounded by the file size first.
class HeaderReader {
 public:
  HeaderReader(const std::string& path, NetcdfHeader* h)
      : path_(path), h_(h), f_(path, std::ios::binary) {
    if (!f_) throw Error(path + ": cannot open the file");
    f_.seekg(0, std::ios::end);
    const std::streamoff end = f_.tellg();
    if (end < 0) throw Error(path + ": cannot read the file");
    size_ = static_cast<std::uint64_t>(end);
    f_.seekg(0);
    h->file_bytes = size_;
  }

  void read() {
    unsigned char magic[4];
    bytes(magic, 4);
    if (magic[0] != 'C' || magic[1] != 'D' || magic[2] != 'F' ||
        (magic[3] != 1 && magic[3] != 2 && magic[3] != 5))
      fail(0, "not a netCDF classic file (no CDF1, CDF2 or CDF5 signature)");
    h_->version = magic[3];
    wide_ = h_->version == 5;
    const std::uint64_t at = pos_;
    h_->numrecs = count();
    if ((!wide_ && h_->numrecs == 0xFFFFFFFFull) || h_->numrecs == ~0ull)
      fail(at, "numrecs is STREAMING, not supported");
    read_dims();
    read_attrs(&h_->attrs, "global attributes");
    read_vars();
    h_->header_bytes = pos_;
    check_data();
  }

 private:
  [[noreturn]] void fail(std::uint64_t at, const std::string& what) const {
    throw Error(path_ + ": netCDF header, byte " + std::to_string(at) + ": " + what);
  }
  std::uint64_t left() const { return size_ - pos_; }
  void bytes(unsigned char* out, std::uint64_t n) {
    if (n > left())
      fail(pos_, "the header is cut short (the file ends at " + std::to_string(size_) + " bytes)");
    f_.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n));
    if (!f_) fail(pos_, "cannot read the file");
    pos_ += n;
  }
  void skip(std::uint64_t n, const char* what) {
    if (n > left())
      fail(pos_, std::string(what) + " of " + std::to_string(n) + " bytes, past the end of the " +
                     std::to_string(size_) + "-byte file");
    pos_ += n;
    f_.seekg(static_cast<std::streamoff>(pos_));
  }
  std::uint64_t be(int n) {
    unsigned char b[8];
    bytes(b, static_cast<std::uint64_t>(n));
    std::uint64_t v = 0;
    for (int i = 0; i < n; ++i) v = (v << 8) | b[i];
    return v;
  }
  std::uint64_t u32() { return be(4); }
  std::uint64_t count() { return be(wide_ ? 8 : 4); }  // NON_NEG
  std::uint64_t offset() { return be(h_->version == 1 ? 4 : 8); }

  // A list's count after its tag, or 0 for ABSENT; each element takes at least min_bytes.
  std::uint64_t list(std::uint32_t tag, std::uint64_t min_bytes, const char* what) {
    const std::uint64_t at = pos_;
    const std::uint64_t t = u32();
    const std::uint64_t n = count();
    if (t == 0 && n == 0) return 0;
    if (t != tag)
      fail(at, std::string("expected the ") + what + " tag " + std::to_string(tag) + ", found " +
                   std::to_string(t));
    if (n > left() / min_bytes)
      fail(at, std::to_string(n) + " " + what + " declared, more than the " +
                   std::to_string(left()) + " bytes left in the file hold");
    return n;
  }

  std::string name() {
    const std::uint64_t at = pos_;
    const std::uint64_t n = count();
    if (n == 0 || n > kMaxName)
      fail(at, "name of " + std::to_string(n) + " bytes (1.." + std::to_string(kMaxName) + ")");
    std::string s(pad4(n), '\0');
    bytes(reinterpret_cast<unsigned char*>(&s[0]), s.size());
    s.resize(n);
    return s;
  }
  int type() {
    const std::uint64_t at = pos_;
    const std::uint64_t t = u32();
    if (t < 1 || t > (wide_ ? 11u : 6u)) fail(at, "bad type " + std::to_string(t));
    return static_cast<int>(t);
  }
  // The smallest encoding of a name (count and 4 bytes).
  std::uint64_t min_name() const { return (wide_ ? 8 : 4) + 4; }

  void read_dims() {
    const std::uint64_t n = list(kTagDim, min_name() + (wide_ ? 8 : 4), "dimensions");
    bool record = false;
    for (std::uint64_t i = 0; i < n; ++i) {
      NetcdfDim d;
      d.name = name();
      const std::uint64_t at = pos_;
      d.length = count();
      if (d.length == 0) {
        if (record) fail(at, "a second record dimension " + q(d.name));
        record = true;
      }
      h_->dims.push_back(d);
    }
  }

  void read_attrs(std::vector<NetcdfAttr>* out, const char* what) {
    const std::uint64_t n = list(kTagAttr, min_name() + 4 + (wide_ ? 8 : 4), what);
    for (std::uint64_t i = 0; i < n; ++i) {
      NetcdfAttr a;
      a.name = name();
      a.type = type();
      const std::uint64_t at = pos_;
      a.count = count();
      std::uint64_t b = 0;
      if (!mul(a.count, type_size(a.type), left(), &b))
        fail(at, "attribute " + q(a.name) + " declares " + std::to_string(a.count) +
                     " values, more than the " + std::to_string(left()) +
                     " bytes left in the file hold");
      skip(pad4(b), "attribute values");
      out->push_back(a);
    }
  }

  void read_vars() {
    const std::uint64_t word = wide_ ? 8 : 4;
    const std::uint64_t n =
        list(kTagVar, min_name() + word + 8 + 4 + word + (h_->version == 1 ? 4 : 8), "variables");
    for (std::uint64_t i = 0; i < n; ++i) {
      NetcdfVar v;
      v.name = name();
      std::uint64_t at = pos_;
      const std::uint64_t nd = count();
      if (nd > kMaxVarDims || nd > left() / word)
        fail(at, "variable " + q(v.name) + " has " + std::to_string(nd) + " dimensions");
      for (std::uint64_t k = 0; k < nd; ++k) {
        at = pos_;
        const std::uint64_t id = count();
        if (id >= h_->dims.size())
          fail(at, "variable " + q(v.name) + ": no dimension " + std::to_string(id));
        if (h_->dims[id].length == 0) {
          if (k != 0) fail(at, "variable " + q(v.name) + ": the record dimension is not its first");
          v.record = true;
        }
        v.dims.push_back(id);
      }
      read_attrs(&v.attrs, "variable attributes");
      v.type = type();
      count();  // vsize: recomputed below, as libnetcdf does
      v.begin = offset();
      // Bytes of the data (of one record): the product of the other dimensions.
      std::uint64_t bytes = type_size(v.type);
      for (std::size_t k = v.record ? 1 : 0; k < v.dims.size(); ++k)
        if (!mul(bytes, h_->dims[v.dims[k]].length, size_, &bytes))
          fail(at, "variable " + q(v.name) + " is larger than the " + std::to_string(size_) +
                       "-byte file");
      v.bytes = bytes;
      h_->vars.push_back(v);
    }
  }

  // Every variable's data (numrecs records of the record variables) lies in the file.
  void check_data() const {
    std::uint64_t recsize = 0, nrec = 0;
    for (const NetcdfVar& v : h_->vars)
      if (v.record) ++nrec, recsize += pad4(v.bytes);
    if (nrec == 1)
      for (const NetcdfVar& v : h_->vars)
        if (v.record) recsize = v.bytes;  // one record variable: records are not padded
    const std::uint64_t end = pos_;
    for (const NetcdfVar& v : h_->vars) {
      std::uint64_t span = v.bytes;
      if (v.record && h_->numrecs > 0) {
        std::uint64_t rest = 0;
        if (!mul(h_->numrecs - 1, recsize, size_, &rest) || rest > size_ - v.bytes)
          fail(end, std::to_string(h_->numrecs) + " records of " + std::to_string(recsize) +
                        " bytes, more than the " + std::to_string(size_) + "-byte file holds");
        span += rest;
      } else if (v.record) {
        span = 0;
      }
      if (v.begin < end || v.begin > size_ || span > size_ - v.begin)
        fail(end, "variable " + q(v.name) + ": data at bytes " + std::to_string(v.begin) + ".." +
                      std::to_string(v.begin + span) + ", outside the data part " +
                      std::to_string(end) + ".." + std::to_string(size_) + " of the file");
    }
  }

  const std::string& path_;
  NetcdfHeader* h_;
  std::ifstream f_;
  std::uint64_t size_ = 0, pos_ = 0;
  bool wide_ = false;
};

const NetcdfDim* find_dim(const NetcdfHeader& h, const std::string& name) {
  for (const NetcdfDim& d : h.dims)
    if (d.name == name) return &d;
  return nullptr;
}

// The variable's dimension names equal names, and its type is one of types.
void expect_var(const std::string& path, const NetcdfHeader& h, const NetcdfVar& v,
                const std::vector<std::string>& names, const std::vector<int>& types) {
  bool ok = v.dims.size() == names.size();
  for (std::size_t k = 0; ok && k < names.size(); ++k) ok = h.dims[v.dims[k]].name == names[k];
  if (!ok) {
    std::string want;
    for (const std::string& n : names) want += (want.empty() ? "" : ", ") + n;
    throw Error(path + ": Exodus II variable " + q(v.name) + " is not defined over (" + want + ")");
  }
  if (std::find(types.begin(), types.end(), v.type) == types.end())
    throw Error(path + ": Exodus II variable " + q(v.name) + " has type " + std::to_string(v.type));
}

void expect_text(const std::string& path, const std::string& owner, const NetcdfAttr& a,
                 std::uint64_t max) {
  if (a.type != kNcChar || a.count > max)
    throw Error(path + ": Exodus II attribute " + q(owner + a.name) + " is not text of at most " +
                std::to_string(max) + " characters");
}

// The values of a 1-D integer variable (big-endian int or int64), empty when there is none.
std::vector<std::int64_t> read_ints(const std::string& path, const NetcdfHeader& h,
                                    const std::string& name) {
  std::vector<std::int64_t> out;
  for (const NetcdfVar& v : h.vars) {
    if (v.name != name || v.record || (v.type != kNcInt && v.type != kNcInt64)) continue;
    const std::uint64_t w = v.type == kNcInt ? 4 : 8;
    std::string bytes(v.bytes, '\0');  // lies in the file: read_netcdf_header checked it
    std::ifstream f(path, std::ios::binary);
    f.seekg(static_cast<std::streamoff>(v.begin));
    f.read(&bytes[0], static_cast<std::streamsize>(bytes.size()));
    if (!f) throw Error(path + ": cannot read Exodus II variable " + q(name));
    for (std::uint64_t i = 0; i + w <= bytes.size(); i += w) {
      std::uint64_t u = 0;
      for (std::uint64_t b = 0; b < w; ++b) u = (u << 8) | static_cast<unsigned char>(bytes[i + b]);
      out.push_back(w == 4 ? static_cast<std::int32_t>(u) : static_cast<std::int64_t>(u));
    }
  }
  return out;
}

// The shapes libexodusii assumes when it reads a variable into a buffer sized from dimensions.
void check_exodus_layout(const std::string& path, const NetcdfHeader& h) {
  const std::vector<int> ints = {kNcInt, kNcInt64}, reals = {kNcFloat, kNcDouble};
  // ex_open and ex_inquire read these into one float or int each.
  static const char* const kScalars[] = {"version",
                                         "api_version",
                                         "api version",
                                         "floating_point_word_size",
                                         "floating point word size",
                                         "file_size",
                                         "int64_status",
                                         "maximum_name_length"};
  for (const NetcdfAttr& a : h.attrs) {
    if (a.name == "title") expect_text(path, "", a, 81);  // MAX_LINE_LENGTH and the NUL
    for (const char* n : kScalars)
      if (a.name == n && (a.count != 1 || a.type == kNcChar))
        throw Error(path + ": Exodus II attribute " + q(a.name) + " is not one number");
  }
  for (const NetcdfVar& v : h.vars) {
    const std::string& n = v.name;
    if (n == "coordx" || n == "coordy" || n == "coordz") {
      expect_var(path, h, v, {"num_nodes"}, reals);
    } else if (n == "coord") {
      expect_var(path, h, v, {"num_dim", "num_nodes"}, reals);
    } else if (n == "eb_prop1" || n == "eb_status") {
      expect_var(path, h, v, {"num_el_blk"}, ints);
    } else if (n == "eb_names") {
      expect_var(path, h, v, {"num_el_blk", "len_name"}, {kNcChar});
    } else if (n.compare(0, 7, "connect") == 0 && n.size() > 7 &&
               n.find_first_not_of("0123456789", 7) == std::string::npos) {
      const std::string k = n.substr(7);
      expect_var(path, h, v, {"num_el_in_blk" + k, "num_nod_per_el" + k}, ints);
      bool typed = false;
      for (const NetcdfAttr& a : v.attrs)
        if (a.name == "elem_type") {
          expect_text(path, n + ":", a, 32);  // MAX_STR_LENGTH: ex_get_block copies it with strcpy
          typed = a.count > 0;
        }
      // ex_get_block copies an uninitialised buffer as the type when it cannot read one.
      if (!typed)
        throw Error(path + ": Exodus II variable " + q(n) + " has no elem_type attribute");
    }
  }
  // An active block (eb_status not 0; every block when there is no eb_status) needs its
  // num_el_in_blkK and connectK, and a block with elements its connectK: ex_get_block's failure
  // path copies an uninitialised buffer as the type. (A null block, status 0, has neither.)
  const NetcdfDim* blocks = find_dim(h, "num_el_blk");
  if (!blocks) return;
  if (blocks->length > h.file_bytes / 4)
    throw Error(path + ": Exodus II header declares " + std::to_string(blocks->length) +
                " element blocks, more than the file holds");
  const std::vector<std::int64_t> status = read_ints(path, h, "eb_status");
  std::set<std::string> names;
  for (const NetcdfDim& d : h.dims) names.insert("dim " + d.name);
  for (const NetcdfVar& v : h.vars) names.insert("var " + v.name);
  for (std::uint64_t k = 1; k <= blocks->length; ++k) {
    const std::string id = std::to_string(k);
    const bool active = status.empty() || (k <= status.size() && status[k - 1] != 0);
    const bool counted = names.count("dim num_el_in_blk" + id) > 0;
    if ((active || counted) && (!counted || names.count("var connect" + id) == 0))
      throw Error(path + ": Exodus II element block " + id + " has no " +
                  (counted ? "connect" : "num_el_in_blk") + id);
  }
}

}  // namespace

void read_netcdf_header(const std::string& path, NetcdfHeader* header) {
  *header = NetcdfHeader();
  HeaderReader(path, header).read();
}

void check_exodus_file(const std::string& path) {
  unsigned char head[8] = {0};
  {
    std::ifstream f(path, std::ios::binary);
    if (!f) throw Error(path + ": cannot open the file");
    f.read(reinterpret_cast<char*>(head), sizeof head);
  }
  static const unsigned char kHdf5[8] = {0x89, 'H', 'D', 'F', '\r', '\n', 0x1a, '\n'};
  if (std::equal(head, head + 8, kHdf5)) return;  // netCDF-4: libhdf5 parses it (header file)
  NetcdfHeader h;
  read_netcdf_header(path, &h);
  check_exodus_layout(path, h);
}

}  // namespace io
}  // namespace tmop
