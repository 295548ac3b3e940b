// The local BSP tree of one object: J. Kovalčík, J. Sochor, "Fast rendering of
// complex dynamic scenes", section 3.1 (object partitioning), traversed as in
// section 3.3 (the near child first, then the far child).
//
// A complex object is "divided recursively by planes until a number of
// triangles in parts drops below threshold level"; the planes are axis-aligned
// and "the triangles intersecting the plane are split up". Built once per mesh
// (the paper's preprocessing phase), in object space: the mesh's vertices,
// which are relative to SceneObject::center.
//
// Splitting (the paper is silent on where the plane goes: "none optimization
// and sophisticated splitting methods were applied", section 5): a node's plane
// is perpendicular to the longest axis of the bounds of its triangle pieces, at
// the median of the pieces' centroids on that axis. A piece lies on the low
// side when all its vertices have coordinate <= the plane's, on the high side
// when all are >= it (a piece in the plane goes low), and is otherwise clipped
// into a polygon on each side (Sutherland-Hodgman), fan-triangulated into
// pieces: the pieces keep the triangle's area (up to rounding) and remember the
// mesh triangle they came from. An intersection point gets the plane's
// coordinate exactly and is clamped to its edge's box, so every piece lies in
// the closed cell its node's planes bound.
//
// A node stays a leaf when:
// - Threshold: it holds at most max_leaf_triangles pieces (the paper's rule);
// - Depth: it is at max_depth (the root is depth 0);
// - Unsplittable: no axis's median plane leaves each side with fewer pieces
//   than the node has (all pieces straddle it, or all lie on one side: e.g.
//   duplicates of one triangle, or every centroid on one plane). Requiring
//   progress on both sides makes the build terminate on any input, coplanar,
//   duplicate and zero-area triangles included; the axes are tried longest
//   first;
// - Budget: the pieces made by splitting reached max_extra_pieces_ratio times
//   the mesh's triangle count, a guard against pathological input (long
//   triangles that straddle every plane), which the paper does not need (its
//   concluding section names the growth of triangles as the method's weak spot).
//
// Transform (section 3.1: "an additional transformation matrix is stored in a
// root of every local tree"): the scene moves objects by translation only
// (Scene::displacementAt), and copies of an object share one mesh, so the tree
// is shared too and stores no transform: every query takes the object's
// translation (objectTranslationAt) and translates boxes and the eye at query
// time. Nothing is rebuilt when the object moves.
//
// Storage: one array of nodes in depth-first pre-order (a node, its low
// subtree, its high subtree) and one array of pieces in leaf order, so every
// node's pieces, inner nodes too, are one contiguous range. Both are reserved
// from an estimate before the build. The tree is read-only once built;
// traversal allocates nothing and is safe from several threads at once.
#pragma once
#include <cassert>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec3.hpp>

#include "culling/scene/scene.h"
#include "grid/aabb.h"

namespace gridcull {

struct ObjectBspParams {
    int max_leaf_triangles = 64;          // >= 1: the paper's threshold
    int max_depth = 24;                   // in [0, kMaxObjectBspDepth]
    double max_extra_pieces_ratio = 4.0;  // >= 0: extra pieces allowed, per mesh triangle
};

constexpr int kMaxObjectBspDepth = 60;

enum class BspLeafReason : uint8_t { Inner, Threshold, Depth, Unsplittable, Budget };

// A triangle piece in object space, and the mesh triangle it is part of.
struct BspTrianglePiece {
    glm::dvec3 v[3];
    int source = 0;  // index of the mesh triangle (indices[3 * source ...])
};

struct ObjectBspNode {
    Aabb cell;     // the subspace: the root's is the mesh bounds, then cut by the planes
    Aabb bounds;   // of the subtree's pieces (inside cell); empty subtree: a point box
    int low = -1;  // children, -1 for a leaf; low: coordinate <= split on `axis`
    int high = -1;
    int axis = -1;  // 0, 1, 2; -1 for a leaf
    double split = 0.0;
    int first_piece = 0;  // the subtree's pieces, contiguous
    int piece_count = 0;
    int depth = 0;
    BspLeafReason reason = BspLeafReason::Inner;

    bool isLeaf() const { return low < 0; }
};

// What the front-to-back traversal shows of a node, in world space.
struct ObjectBspNodeView {
    int id = 0;  // index into nodes()
    int depth = 0;
    Aabb bounds;  // ObjectBspNode::bounds translated by the object's translation
    bool leaf = false;
    int first_piece = 0;
    int piece_count = 0;
};

class ObjectBsp {
public:
    static constexpr int kRoot = 0;

    ObjectBsp() = default;
    // Builds the tree of `mesh` (its triangles in object space). Cost:
    // O(n log n * depth) for n triangles; allocates (preprocessing).
    explicit ObjectBsp(const TriangleMesh& mesh, const ObjectBspParams& params = {}) {
        build(mesh, params);
    }
    void build(const TriangleMesh& mesh, const ObjectBspParams& params = {});

    const ObjectBspParams& params() const { return params_; }
    bool empty() const { return nodes_.empty(); }  // before build
    int nodeCount() const { return int(nodes_.size()); }
    int leafCount() const { return leaf_count_; }
    int pieceCount() const { return int(pieces_.size()); }
    int sourceTriangleCount() const { return source_triangles_; }
    int height() const { return height_; }  // deepest node's depth
    // Bytes the node and piece arrays hold (capacity, not size).
    size_t memoryBytes() const {
        return nodes_.capacity() * sizeof(ObjectBspNode) +
               pieces_.capacity() * sizeof(BspTrianglePiece);
    }

    const std::vector<ObjectBspNode>& nodes() const { return nodes_; }
    const ObjectBspNode& node(int i) const {
        assert(i >= 0 && i < nodeCount());
        return nodes_[size_t(i)];
    }
    const std::vector<BspTrianglePiece>& pieces() const { return pieces_; }
    const BspTrianglePiece& piece(int i) const {
        assert(i >= 0 && i < pieceCount());
        return pieces_[size_t(i)];
    }
    // A node's bounds in world space, for an object translated by `translation`.
    Aabb worldBounds(int i, const glm::dvec3& translation) const {
        return node(i).bounds.translated(translation);
    }

    // Pre-order from `eye` (world space) for the object translated by
    // `translation`: a node, then its child on the eye's side of the plane (low
    // when eye < split in object space, high otherwise), then the other one.
    // visit(const ObjectBspNodeView&) returns false to skip the node's subtree.
    // Allocates nothing.
    template <typename Visitor>
    void traverseFrontToBack(const glm::dvec3& eye, const glm::dvec3& translation,
                             Visitor&& visit) const {
        if (nodes_.empty()) return;
        visitNode(kRoot, eye - translation, translation, visit);
    }

private:
    template <typename Visitor>
    void visitNode(int i, const glm::dvec3& eye_local, const glm::dvec3& translation,
                   Visitor& visit) const {
        const ObjectBspNode& n = nodes_[size_t(i)];
        const ObjectBspNodeView view{i,          n.depth,       n.bounds.translated(translation),
                                     n.isLeaf(), n.first_piece, n.piece_count};
        if (!visit(view) || n.isLeaf()) return;
        const bool low_first = eye_local[n.axis] < n.split;
        visitNode(low_first ? n.low : n.high, eye_local, translation, visit);
        visitNode(low_first ? n.high : n.low, eye_local, translation, visit);
    }

    struct BuildState;
    int buildNode(BuildState& state, std::vector<BspTrianglePiece>& work, const Aabb& cell,
                  int depth);

    ObjectBspParams params_;
    std::vector<ObjectBspNode> nodes_;
    std::vector<BspTrianglePiece> pieces_;
    int source_triangles_ = 0;
    int leaf_count_ = 0;
    int height_ = 0;
};

// The translation that takes an object's mesh (object space) to world space at
// time t: SceneObject::center plus the motion's displacement.
inline glm::dvec3 objectTranslationAt(const Scene& scene, const SceneObject& object, double t) {
    return object.center + scene.displacementAt(object, t);
}

// Area of a triangle (world units squared).
double triangleArea(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c);

// Clips triangle (a, b, c) by the plane x[axis] = split into pieces on the
// low side (x[axis] <= split) and the high side (>= split), appended to `low`
// and `high` with `source`. Every intersection point is shared by both sides,
// has x[axis] == split exactly and lies in its edge's box. A triangle wholly on
// one side goes there whole (in the plane: low). Used by the build; public for
// the tests.
void clipTriangle(const glm::dvec3& a, const glm::dvec3& b, const glm::dvec3& c, int source,
                  int axis, double split, std::vector<BspTrianglePiece>& low,
                  std::vector<BspTrianglePiece>& high);

}  // namespace gridcull
