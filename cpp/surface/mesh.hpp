// Output of tessellation: an indexed triangle mesh laid out like three.js
// ParametricGeometry(func, slices = nu, stacks = nv): vertex (i, j) (u index i, v index j) is
// at j*(nu+1)+i; two triangles per cell.
#pragma once
#include <cstdint>
#include <vector>

#include "surface/separable_surface.hpp"

namespace pdesurf {

struct Mesh {
  int nu = 0, nv = 0;
  std::vector<float> positions;  // 3 per vertex
  std::vector<float> normals;    // 3 per vertex, unit X_u × X_v (see tessellate)
  std::vector<float> uvs;        // 2 per vertex, (i/nu, j/nv)
  std::vector<uint32_t> indices; // 6 per cell
  // With curvature (see surface/curvature.hpp): mean H and Gaussian K per vertex, from the
  // surface's analytic second derivatives; 0 at degenerate vertices (X_u × X_v = 0), counted.
  std::vector<float> meanCurvature, gaussCurvature;
  int degenerateVertices = 0;
  size_t vertexCount() const { return positions.size() / 3; }
};

// Double-precision samples of X, X_u, X_v on the same grid (3 per vertex each).
struct GridSamples {
  int nu = 0, nv = 0;
  std::vector<double> u, v;
  std::vector<double> X, Xu, Xv;
};

Mesh tessellate(const SeparableSurface& s, int nu, int nv, bool curvature = false);
// The same into an existing mesh: its buffers are reused, and uvs and indices (which depend
// only on the grid) are rebuilt only when the grid changes. For repeated solves (sliders).
void tessellateInto(const SeparableSurface& s, int nu, int nv, Mesh& out, bool curvature = false);
GridSamples sampleGrid(const SeparableSurface& s, int nu, int nv);

}  // namespace pdesurf
