#pragma once
// Builds the adaptive cache's cells and nodes: base cells over the light
// space, then, level by level, a unit light traced at each cell's centre and
// compared with the blend of the cell's corners over every scene vertex; the
// worst cells are split while the budget of traced lights lasts. A centre
// traced for a cell that is not split stays as that cell's centre node.
#include "hilight/light_cache.hpp"
#include "hilight/light_cache_nodes.hpp"
#include "octree_cells.hpp"

namespace hilight::adaptive {

struct RefineSettings {
  int cells = 8;            ///< base lattice: the grid cache's nodes at this many cells along the longest axis
  int depth = 1;            ///< times a base cell may be split
  double tolerance = 0.05;  ///< split when the blend's relative error at the centre is above this
  double growth = 1.5;      ///< traced lights in all (nodes and split tests) over the base lattice's
};

/// Fills `tree` and `nodes` for the scene of `in`.
void refine_cells(const LightCacheScene& in, const RefineSettings& settings, CellTree& tree, NodeResponses& nodes);

} // namespace hilight::adaptive
