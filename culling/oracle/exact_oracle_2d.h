// The 2D half of the exact oracle (culling/oracle/exact_oracle.h) without sampling:
// the exact lower envelope, over the wedge's angles, of the objects' boundaries as
// seen from the camera, cut at far (2D has no near plane).
//
// The wedge [0, fov] (relative angles, culling/oracle/angular_shape_2d.h) is kept as
// a sorted list of pieces, each owned by the object nearest the camera for every
// angle inside it, or by none. Objects are drawn front to back (by a lower bound of
// their distance). Drawing object B visits only the pieces inside B's analytic
// angular interval (tangent angles of a circle, the running angle of a box's or
// polygon's vertices) whose owner A may lie behind B somewhere (A's farthest point,
// capped at far, beyond B's nearest), and cuts each such piece at the event angles
// (culling/oracle/angular_events.h): A's and B's vertices or tangents, B's
// crossings of the far circle, and the crossings of A's and B's boundaries. Between
// two consecutive events neither depth jumps and the two boundaries do not cross,
// so which of A and B is nearer is the same for every ray; one ray through the
// middle of each elementary interval, intersected exactly
// (culling/scene/ray_intersect.h), decides it for the whole interval. Adjacent
// pieces of one owner merge. An object is visible iff it owns a piece at the end
// (or ties its owner, below). Source: none published; this is the classic lower
// envelope of curves in angle (as in 2D hidden-line removal), written for the oracle.
//
// Precision and decisions:
//  - Exact up to floating point: event angles carry a few ulps of error, so an
//    elementary interval narrower than kMinPieceWidth (about 64 ulps of 2 pi) is not
//    tested and keeps its owner; a visible span that narrow is missed, and a piece
//    that narrow does not make its owner visible.
//  - An object met only at a single angle (a tangent, two silhouettes touching
//    exactly as seen from the camera) covers a set of measure zero: not visible.
//  - Ties: where two objects are at the same distance (within a relative
//    kTieTolerance) along a whole interval, both are seen: their boundaries
//    coincide there (e.g. overlapping boxes sharing a face), and a point of that
//    boundary belongs to both closed solids. The piece keeps the first drawn as
//    owner and the second as `tied`; a third object tied there is not reported.
//  - A camera inside or on the boundary of a solid sees only it; the first such
//    object drawn wins, as in the sampled sweep.
// Cost: the pieces visited per object, times (edges of the owner x edges of the
// object) for the crossings; objects wholly behind the pieces they would cover are
// skipped without a ray. Nothing allocates after reserve() unless an envelope
// outgrows its reserve (then once, the capacity is kept).
#pragma once
#include <cstddef>
#include <cstdint>
#include <vector>

#include "culling/oracle/angular_shape_2d.h"
#include "culling/scene/camera.h"

namespace gridcull {

class AngularEnvelope {
public:
    // 64 ulps of 2 pi: event angles are computed to a few ulps (atan2 of points
    // that are themselves rounded), so narrower intervals cannot be told apart
    // from a single angle.
    static constexpr double kMinPieceWidth = 64 * 8.881784197001252e-16;
    // Relative difference below which two distances along a ray are one surface
    // (coincident faces of overlapping objects, computed from different segments).
    static constexpr double kTieTolerance = 1e-9;

    // Room for `objects` objects with `vertices` polygon and box vertices in all, the
    // largest shape having `largest` vertices.
    void reserve(size_t objects, size_t vertices, size_t largest);
    // Takes the camera and clears the wedge.
    void begin(const Camera& camera);

    // A lower bound of the distance from the camera to any point of the shape.
    double minDistanceOfCircle(const glm::dvec3& center, double radius) const;
    double minDistanceOfBox(const Aabb& box) const;

    // Each draw puts object `index` on the envelope; false when it lies wholly
    // beyond far or outside the wedge. Call front to back.
    bool drawCircle(int index, const glm::dvec3& center, double radius);
    bool drawBox(int index, const Aabb& box);
    bool drawPolygon(int index, const glm::dvec3* points, size_t count, const glm::dvec3& offset);

    // Sets seen[index] = 1 for every owner of a piece.
    void markVisible(std::vector<char>& seen) const;
    // Rays cast since begin(), one per elementary interval tested.
    int64_t raysCast() const { return rays_; }

private:
    struct Piece {
        double begin, end;
        int32_t owner;  // -1: no object
        int32_t tied;   // an object at the owner's distance over the whole piece; -1: none
        double bound;   // the owner's farthest distance within far; infinity for none
    };

    bool draw(int index, const AngularShape& shape);
    // Puts the object on the pieces within [from, to] (inside [0, fov]).
    void insert(int index, double from, double to);
    // Cuts [from, to] of a piece owned by `owner` at the events and decides each
    // elementary interval between it and `index`.
    void split(const Piece& piece, int index, double from, double to);
    void push(const Piece& piece);

    AngularFrame frame_;
    std::vector<Piece> pieces_, scratch_;
    std::vector<double> events_;
    std::vector<AngularShape> shapes_;    // per object index, as drawn this frame
    std::vector<AngularExtent> extents_;  // per object index
    bool filled_ = false;                 // a solid holds the camera
    int64_t rays_ = 0;
};

}  // namespace gridcull
