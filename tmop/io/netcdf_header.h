// tmop/io/netcdf_header.h
// A strict reader of the header of a netCDF classic file (CDF-1 classic, CDF-2 64-bit offset,
// CDF-5 64-bit data; the NetCDF Classic Format Specification), so that a crafted header is
// refused before libnetcdf allocates what it declares. Internal to io/ (exodus.cc).
//
//   read_netcdf_header(path, &header): parses magic, numrecs, dimensions, global attributes and
//     variables (their attributes, type, begin) and checks, before anything is allocated from a
//     count, that every count fits in the bytes left in the file, and after parsing that
//     - every attribute's values lie in the file (they are part of the header);
//     - names are 1..256 bytes (NC_MAX_NAME), at most one dimension is the record dimension and a
//       variable uses it only as its first dimension; dimension ids exist; types are 1..6
//       (CDF-1/2) or 1..11 (CDF-5);
//     - a non-record variable's data, begin + (product of its dimensions x type size, computed:
//       the header's vsize is not trusted, libnetcdf recomputes it too), lies in the file after
//       the header, and so do numrecs records of the record variables (record size = the sum of
//       their padded slices, the first slice at its begin);
//     - numrecs is not STREAMING (0xFFFFFFFF: libnetcdf does not write it).
//     Failure: Error "PATH: netCDF header, byte N: WHAT" (one line).
//   check_exodus_file(path): what read_exodus calls before ex_open. A file that starts with the
//     HDF5 signature (netCDF-4, "\x89HDF\r\n\x1a\n"; meshio 5 writes these) is passed on
//     unchecked: libhdf5 parses it as it parses every CGNS file, and read_exodus bounds every
//     count it allocates from by the file size. That is the residual risk of the format (fuzzing
//     found libhdf5 1.10.8 freeing an invalid pointer on a damaged group of such a file inside
//     nc_open: tests/fuzz/regressions/exo/hdf5_invalid_free.exo, docs/fuzzing.md), which the
//     isolated read (isolated_read.h: the tools read such files in a child process) turns into a
//     one-line error; the layout
//     check below is not applied to netCDF-4 files. Anything else must be a
//     classic file that read_netcdf_header accepts and whose Exodus variables have the shapes
//     libexodusii assumes when it reads them into buffers sized from dimensions: coordx/coordy/
//     coordz (num_nodes), coord (num_dim, num_nodes), eb_prop1 and eb_status (num_el_blk),
//     eb_names (num_el_blk, len_name), connectK (num_el_in_blkK, num_nod_per_elK) of an integer
//     type with an elem_type (ex_get_block copies an uninitialised buffer otherwise), a
//     num_el_in_blkK and connectK for every active block K (eb_status not 0, read from the file),
//     elem_type as text of at most 32 bytes (MAX_STR_LENGTH: ex_get_block strcpy's it, and 33
//     without a NUL run past its buffer), the global title of at most 81 (MAX_LINE_LENGTH and the
//     NUL), and the global attributes ex_open reads into one float or int (version, api_version,
//     floating_point_word_size, file_size, int64_status, maximum_name_length; also the old
//     spellings with spaces) one number each. Failure: Error "PATH: ..." (one line).
#ifndef TMOP_IO_NETCDF_HEADER_H_
#define TMOP_IO_NETCDF_HEADER_H_

#include <cstdint>
#include <string>
#include <vector>

namespace tmop {
namespace io {

// nc_type codes of the classic formats (7..11 only in CDF-5).
enum NetcdfType : int {
  kNcByte = 1,
  kNcChar = 2,
  kNcShort = 3,
  kNcInt = 4,
  kNcFloat = 5,
  kNcDouble = 6,
  kNcUbyte = 7,
  kNcUshort = 8,
  kNcUint = 9,
  kNcInt64 = 10,
  kNcUint64 = 11,
};

struct NetcdfDim {
  std::string name;
  std::uint64_t length = 0;  // 0: the record (unlimited) dimension
};

struct NetcdfAttr {
  std::string name;
  int type = 0;
  std::uint64_t count = 0;  // values
};

struct NetcdfVar {
  std::string name;
  std::vector<std::uint64_t> dims;  // dimension ids, outermost first
  std::vector<NetcdfAttr> attrs;
  int type = 0;
  std::uint64_t begin = 0;  // file offset of the data (of the first record's slice)
  std::uint64_t bytes = 0;  // data bytes (one record's slice for a record variable), computed
  bool record = false;
};

struct NetcdfHeader {
  int version = 0;  // 1, 2 or 5 (CDF-1, CDF-2, CDF-5)
  std::uint64_t numrecs = 0;
  std::vector<NetcdfDim> dims;
  std::vector<NetcdfAttr> attrs;  // global
  std::vector<NetcdfVar> vars;
  std::uint64_t header_bytes = 0;  // where the header ends
  std::uint64_t file_bytes = 0;
};

void read_netcdf_header(const std::string& path, NetcdfHeader* header);

void check_exodus_file(const std::string& path);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_NETCDF_HEADER_H_
