// Solids: a closed, consistently oriented triangle mesh taken as the solid it bounds
// (docs/design.md, "Solids").
//
// Closed and consistently oriented: no triangle repeats a vertex index, and every edge
// {a, b} (body.h) is a side of exactly two triangles, once as a -> b and once as
// b -> a in their vertex order. check_solid refuses anything else with an Input_error
// naming the first offending edge (in the edge order of body.h) by its two vertex
// indices and a triangle using it.
//
// The solid of such a mesh is the closure of the points of nonzero winding number: for
// outward or inward orientation alike, nested shells included. winding_number is exact
// (rationals) and decides degenerate rays by a symbolic perturbation, never by a
// tolerance:
//   the ray from p along +x is moved to start at p' = p + (0, e, e^2) for an
//   infinitesimal e > 0. In the projection onto the (y, z) plane, p' lies on no line
//   through two distinct projected vertices (a y + b z + c vanishes at p' only when
//   a = b = 0), so p' is inside or outside every projected triangle, never on an edge
//   or vertex. The sign of each 2D orientation at p' is that of its leading nonzero
//   term in (1, e, e^2). A triangle whose projection has zero area is met by no such
//   ray (skipped). For p off the surface, p' has p's winding number (e is
//   infinitesimal) and the hit point of a counted triangle is not at p's x (else p
//   would lie on the closed triangle), so its side is decided unperturbed. The winding
//   number is the sum, over the triangles whose projection holds p' and whose plane
//   the ray meets beyond p, of the sign of the projected area (the triangle's normal's
//   x component).
#pragma once
#include <cstdint>
#include <vector>

#include "motion/body.h"

namespace pccd::motion {

// Input_error "triangles: edge (a, b) of triangle t ..." when mesh is not closed and consistently
// oriented (see above); "triangles[t]: ..." for a triangle that repeats an index.
void check_solid(const Mesh_body &mesh);

// The winding number of the closed, consistently oriented mesh about p (p in the mesh's
// own frame), for p off the surface (the callers' contract). *on_surface (when not null)
// is set, and 0 returned, when the test meets p on a triangle (not every point on the
// surface is noticed).
long winding_number(const Mesh_body &mesh, const Point3_q &p, bool *on_surface = nullptr);
// The same over the triangles tris[0 .. n) only: the caller leaves out none whose (y, z)
// bounding box holds (p_y, p_z) (the others never count).
long winding_number(const Mesh_body &mesh, const Point3_q &p, const uint32_t *tris, size_t n,
                    bool *on_surface = nullptr);

// One vertex of each connected component of the mesh's surface (triangles sharing a
// vertex are connected), the least index of each, ascending. Vertices used by no
// triangle are not part of the surface and never listed.
std::vector<uint32_t> component_vertices(const Mesh_body &mesh);

}  // namespace pccd::motion
