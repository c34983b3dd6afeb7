// Mesh simplification by quadric error metrics (Garland & Heckbert 1997), following the lecture's
// "Lazy Greedy Local Simplification" and "Quadric Error Metric" slides
// (000_c9f7e5de708ecbb3.txt L5955-6033): edge collapses ordered by their quadric cost in a
// priority queue whose entries are re-costed only when popped dirty.
#pragma once

#include "scene/mesh.hpp"

#include <cstddef>
#include <optional>

namespace pl::scene {

// When to stop. Collapses run in cost order until the triangle count is <= `triangles` (or
// `ratio` x the input's; at most one of the two); with `max_error`, a collapse whose error
// (below) exceeds it is never made, and the run also ends when no legal collapse is left.
struct SimplifyTarget {
    std::optional<double> ratio;  // (0, 1]
    std::optional<size_t> triangles;
    std::optional<double> max_error;  // mesh units
};

struct SimplifyOptions {
    SimplifyTarget target;
    // Geomorph: continue the same collapse sequence to this coarser target and record, for every
    // vertex of the result, where it ends up (the sequence is deterministic and greedy, so the
    // coarser mesh is exactly what `target = morph` alone would give).
    std::optional<SimplifyTarget> morph;
};

// Per-vertex geomorph target, vertex binding 1 (locations 4..6; see docs/format.md).
struct MorphVertex {
    float position[3];
    float normal[3];
    float uv[2];
};
static_assert(sizeof(MorphVertex) == 8 * sizeof(float), "MorphVertex layout is part of the shader contract");

struct SimplifyStats {
    size_t input_triangles = 0;   // non-degenerate triangles after welding (what `ratio` scales)
    size_t output_triangles = 0;  // of `mesh`
    size_t morph_triangles = 0;   // of the morph target, when asked for
    size_t collapses = 0;
    size_t rejected = 0;          // popped clean but illegal (flip, topology, seam, border pinch)
    size_t recosted = 0;          // popped dirty and re-inserted
    double max_error = 0;         // largest error of a collapse made (see collapse_error)
    double min_cost = 0;          // smallest cost ever computed (>= 0 up to rounding)
};

struct Simplified {
    Mesh mesh;
    std::vector<MorphVertex> morph;  // one per mesh vertex when options.morph is set
    std::vector<uint32_t> source_triangle;  // per output triangle: the input triangle it was
    SimplifyStats stats;
};

// The error of a collapse, in mesh units: the area-weighted RMS distance of the new vertex to the
// planes of the faces merged into it, sqrt(cost / total weight).
double collapse_error(double cost, double weight);

// Simplifies a triangle list. Positions are welded first (seams keep their attribute copies),
// zero-area triangles are dropped, and the result keeps the input's vertex layout: each output
// vertex is an input vertex (a "wedge") whose position moved to its collapse's optimum and whose
// normal/uv/tangent were interpolated along the collapsed edge. Deterministic: ties go to the
// lower edge index. Tangents are recomputed by the caller if it wants them exact.
Simplified simplify(const Mesh& mesh, const SimplifyOptions& options);

} // namespace pl::scene
