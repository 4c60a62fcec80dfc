// tmop/io/surface_scan.h
// The validating pass over .obj / .off / .ply files that runs before OpenMesh reads them
// (internal to io/). OpenMesh's readers report no positions and silently skip what they cannot
// use (an out-of-range or repeated face index drops the face, a garbage OBJ line is ignored, a NaN
// is read as a coordinate), so tmop checks the whole file first and reports the first problem as
// "FILE:LINE: what" (text) or "FILE:byte N: what" (binary data).
//
// Input: the path (for messages), the lower-case extension and the whole file. Output: the
// vertex count and the faces (0-based vertex indices, 3 or 4 per face, in file order) with the
// byte offset of each face record, so that read_openmesh can check OpenMesh's reading against it
// and locate a disagreement. Throws tmop::Error on the first problem; declared counts are
// checked against the file size before anything is allocated.
//
// What is checked: OBJ statements (v, vt, vn, f and the grouping / material / free-form
// statements OpenMesh skips; anything else is an error), vertex coordinates finite, face indices
// in range (OBJ: among the vertices defined so far, negative = relative), 3 or 4 distinct
// vertices per face, OFF / PLY headers, record counts, truncation and data after the last record.
#ifndef TMOP_IO_SURFACE_SCAN_H_
#define TMOP_IO_SURFACE_SCAN_H_

#include <cstdint>
#include <string>
#include <vector>

namespace tmop {
namespace io {

struct SurfaceScan {
  std::int64_t num_vertices = 0;
  std::vector<std::int32_t> face_offsets{0};  // face f has nodes [offsets[f], offsets[f + 1])
  std::vector<std::int32_t> face_nodes;
  std::vector<std::size_t> face_pos;  // byte offset of each face's record in the file
  bool binary = false;                // positions are reported as bytes, not lines
  std::int64_t num_faces() const { return static_cast<std::int64_t>(face_pos.size()); }
};

SurfaceScan scan_surface(const std::string& path, const std::string& ext, const std::string& data);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_SURFACE_SCAN_H_
