// tmop/io/cgns_bc.h
// CGNS boundary conditions (ZoneBC_t / BC_t) <-> names of boundary regions (cgns_bc.cc), used by
// cgns.cc. Only with libcgns (TMOP_WITH_CGNS).
//
// Write: one BC_t per region R > 0 that has cells of dimension mesh.dim() - 1 (faces of a 3D
// mesh, edges of a 2D one), named by the region's physical name when it is a valid CGNS name (1
// to 32 characters, no '/', not taken by an earlier BC), else "Region_R"; BCType FamilySpecified
// with a FamilyName of the same name and a Family_t of that name in the base (what Pointwise and
// ICEM write: solvers that set up boundaries by family (Fluent, STAR-CCM+, CFD++) and those that
// read BC names (VTK, ParaView, SU2's section names are kept too) find the name); GridLocation
// FaceCenter (3D) / EdgeCenter (2D); PointRange when the region's cells are one contiguous range
// of element numbers, else PointList.
// Read: BC_t nodes with an element location (FaceCenter, EdgeCenter, or the ElementRange /
// ElementList point sets) name the regions of the cells they list, which must be cells of
// dimension base cell dimension - 1 of the zone's sections: when they are exactly the cells of
// one region of that dimension, that region takes the BC's name (over a section's); otherwise the
// listed cells move to a new region (the largest + 1) named by the BC. No cells are created (CGNS
// boundary faces are always element sections). A BC named "Region_R" names nothing. Vertex and
// cell-centred BCs are ignored.
#ifndef TMOP_IO_CGNS_BC_H_
#define TMOP_IO_CGNS_BC_H_

#ifdef TMOP_WITH_CGNS

#include <cgnslib.h>

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

// The cells read from one element section: element numbers start..start + count - 1 are the
// mesh's cells first..first + count - 1.
struct CgSectionCells {
  cgsize_t start = 0;
  cgsize_t count = 0;
  int first = 0;
};

// Writes the ZoneBC_t of zone Z of base B; elem_number[c] is cell c's CGNS element number.
void write_cgns_bcs(const std::string& path, int fn, int B, int Z, const Mesh& mesh,
                    const std::vector<cgsize_t>& elem_number);

// Reads the BCs of zone Z of base 1 (cell dimension cell_dim) whose sections gave `sections`.
void read_cgns_bcs(const std::string& path, int fn, int Z, int cell_dim, std::uint64_t file_size,
                   const std::vector<CgSectionCells>& sections, Mesh* mesh);

}  // namespace io
}  // namespace tmop

#endif  // TMOP_WITH_CGNS
#endif  // TMOP_IO_CGNS_BC_H_
