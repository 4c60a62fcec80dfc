// tmop/io/exodus_sides.h
// Exodus II side sets <-> boundary cells (exodus_sides.cc), used by exodus.cc.
//
// Side numbering (Exodus II manual, SAND92-2137, "side set node ordering"; 1-based, in Exodus
// corner positions): HEX 1:1265 2:2376 3:3487 4:1584 5:1432 6:5678; TETRA 1:124 2:234 3:143
// 4:132; WEDGE 1:1254 2:2365 3:1463 4:132 5:456; PYRAMID 1:125 2:235 3:345 4:154 5:1432; 2D TRI
// 1:12 2:23 3:31, QUAD 1:12 2:23 3:34 4:41. Each side's corners are listed so that its
// right-hand normal points out of the element (the Exodus convention, tmop's facet convention:
// cell_type.h), and the same for the quadratic forms; sides of 1D elements and of 2D elements in
// a 3D file (shells: sides 1-2 are faces there) are not used.
#ifndef TMOP_IO_EXODUS_SIDES_H_
#define TMOP_IO_EXODUS_SIDES_H_

#include <cstdint>
#include <string>
#include <vector>

#include "tmop/mesh/mesh.h"

namespace tmop {
namespace io {

// Number of Exodus sides of an element of type t in a file of num_dim dimensions: 0 when side
// sets on it are not read or written (1D cells, 2D cells when num_dim is 3, vertices).
int exodus_num_sides(CellType t, int num_dim);

// The boundary cell that is side `side` (1-based) of element `cell` of `mesh`: its type (line2,
// line3, tri3, tri6, quad4, quad8 or quad9, by the element's order and face nodes) and its nodes
// in Gmsh order, corners in the side's outward order. False when side is out of 1..num_sides.
bool exodus_side_cell(const Mesh& mesh, int cell, int side, int num_dim, CellType* type,
                      std::int32_t* nodes);

// One side set to write: id = region (> 0), name (may be empty), (element, side) pairs with
// 1-based Exodus element numbers.
struct ExoSideSet {
  int id = 0;
  std::string name;
  std::vector<int> elems, sides;
};

// The side sets of mesh: one per region > 0 whose cells of dimension mesh.dim() - 1 are all
// sides (same type, same node set) of elements of the mesh, in increasing region order.
// elem_number[c] is cell c's 1-based Exodus element number. Empty when num_dim != mesh.dim().
std::vector<ExoSideSet> plan_exodus_side_sets(const Mesh& mesh, const std::vector<int>& elem_number,
                                              int num_dim);

#ifdef TMOP_WITH_EXODUS
// The names of the n entities of ex_entity_type type (EX_ELEM_BLOCK, EX_SIDE_SET) in id order,
// "" when unnamed or unreadable.
std::vector<std::string> exodus_names(int exo, int type, int n);
// Writes the side sets (ids, (element, side) lists, names) to the open Exodus file exo.
void write_exodus_side_sets(const std::string& path, int exo, const std::vector<ExoSideSet>& sets);
// Reads the nss side sets of the open file exo of file_size bytes and num_dim dimensions; the
// mesh's cells first .. first + num_elems - 1 are its elements 1..num_elems. Each (element,
// side) becomes a boundary cell with region = set id and the set's name, unless a cell with the
// same node set exists already (from a block or an earlier set): then the set only names that
// cell's (dimension, region) if it has no name.
void read_exodus_side_sets(const std::string& path, int exo, std::uint64_t file_size, int nss,
                           int num_dim, int first, int num_elems, Mesh* mesh);
#endif

}  // namespace io
}  // namespace tmop

#endif  // TMOP_IO_EXODUS_SIDES_H_
