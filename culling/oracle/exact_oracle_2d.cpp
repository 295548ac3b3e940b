#include "culling/oracle/exact_oracle_2d.h"

#include <algorithm>
#include <cassert>
#include <cmath>
#include <limits>

#include <glm/trigonometric.hpp>

#include "culling/oracle/angular_events.h"

namespace gridcull {

namespace {

constexpr double kTwoPi = 6.283185307179586476925286766559;
constexpr double kInfinity = std::numeric_limits<double>::infinity();
// The analytic interval is widened by this much on each side before it is cut:
// the true ends are events themselves, so the margin only adds intervals where a
// ray finds the object missing, and no rounding of the ends can lose a sliver.
constexpr double kIntervalMargin = 1e-12;

// Whether two distances along one ray are the same surface: two objects whose
// boundaries coincide (e.g. overlapping boxes sharing a face) compute it from
// different segments and round differently. The brute-force reference of the
// oracle tests uses the same relative tolerance.
bool sameDistance(double a, double b) {
    return std::abs(a - b) <= AngularEnvelope::kTieTolerance * std::max(a, b);
}

}  // namespace

void AngularEnvelope::reserve(size_t objects, size_t vertices, size_t largest) {
    shapes_.resize(std::max(shapes_.size(), objects));
    extents_.resize(std::max(extents_.size(), objects));
    // Each drawn object adds at most a few pieces per vertex in practice (the
    // envelope of n segments has O(n alpha(n)) pieces); 8 per shape and vertex
    // leaves ample room.
    const size_t pieces = 8 * (objects + vertices) + 64;
    pieces_.reserve(pieces);
    scratch_.reserve(pieces);
    // One piece's events: both ends, both shapes' silhouettes, the far crossings
    // (two per edge) and the crossings (two per pair of edges, or of edge and circle).
    const size_t m = std::max<size_t>(largest, 4);
    events_.reserve(2 * m * m + 6 * m + 8);
}

void AngularEnvelope::begin(const Camera& camera) {
    frame_.set(camera, glm::radians(std::clamp(camera.fov_deg, 0.0, 360.0)));
    pieces_.clear();
    pieces_.push_back({0.0, frame_.fov, -1, -1, kInfinity});
    filled_ = false;
    rays_ = 0;
}

double AngularEnvelope::minDistanceOfCircle(const glm::dvec3& center, double radius) const {
    return std::hypot(center.x - frame_.origin.x, center.y - frame_.origin.y) - radius;
}

double AngularEnvelope::minDistanceOfBox(const Aabb& box) const {
    const double dx = std::max({box.min.x - frame_.origin.x, 0.0, frame_.origin.x - box.max.x});
    const double dy = std::max({box.min.y - frame_.origin.y, 0.0, frame_.origin.y - box.max.y});
    return std::hypot(dx, dy);
}

bool AngularEnvelope::drawCircle(int index, const glm::dvec3& center, double radius) {
    return draw(index, AngularShape::makeCircle(center, radius));
}

bool AngularEnvelope::drawBox(int index, const Aabb& box) {
    return draw(index, AngularShape::makeBox(box));
}

bool AngularEnvelope::drawPolygon(int index, const glm::dvec3* points, size_t count,
                                  const glm::dvec3& offset) {
    if (count < 3) return false;
    return draw(index, AngularShape::makePolygon(points, count, offset));
}

bool AngularEnvelope::draw(int index, const AngularShape& shape) {
    if (size_t(index) >= shapes_.size()) {  // a larger scene than reserve() was told
        shapes_.resize(size_t(index) + 1);
        extents_.resize(size_t(index) + 1);
    }
    const AngularExtent extent = angularExtent(shape, frame_);
    shapes_[size_t(index)] = shape;
    extents_[size_t(index)] = extent;
    if (extent.contains_camera) {
        if (!filled_) {
            pieces_.clear();
            pieces_.push_back({0.0, frame_.fov, index, -1, 0.0});
            filled_ = true;
        }
        return true;
    }
    if (extent.min_distance > frame_.far) return false;
    double lo = extent.lo - kIntervalMargin, hi = extent.hi + kIntervalMargin;
    if (hi - lo >= kTwoPi) {
        insert(index, 0.0, frame_.fov);
        return true;
    }
    // Wrap lo into [0, 2 pi); the interval may then run past 2 pi, back to the
    // wedge's first edge.
    const double turns = std::floor(lo / kTwoPi);
    lo -= turns * kTwoPi;
    hi -= turns * kTwoPi;
    bool any = false;
    if (lo < frame_.fov) {
        insert(index, lo, std::min(hi, frame_.fov));
        any = true;
    }
    if (hi > kTwoPi) {
        insert(index, 0.0, std::min(hi - kTwoPi, frame_.fov));
        any = true;
    }
    return any;
}

void AngularEnvelope::push(const Piece& piece) {
    if (!scratch_.empty() && scratch_.back().owner == piece.owner &&
        scratch_.back().tied == piece.tied && scratch_.back().end == piece.begin) {
        scratch_.back().end = piece.end;
        return;
    }
    scratch_.push_back(piece);
}

void AngularEnvelope::insert(int index, double from, double to) {
    if (!(from < to)) return;
    const double near = extents_[size_t(index)].min_distance;
    // The pieces that overlap [from, to], and one neighbour each side so that
    // pieces of one owner merge across the ends.
    size_t first = size_t(std::partition_point(pieces_.begin(), pieces_.end(),
                                               [&](const Piece& p) { return p.end <= from; }) -
                          pieces_.begin());
    if (first > 0) --first;
    size_t last = first;
    while (last < pieces_.size() && pieces_[last].begin < to) ++last;
    if (last < pieces_.size()) ++last;

    scratch_.clear();
    bool changed = false;
    for (size_t j = first; j < last; ++j) {
        const Piece piece = pieces_[j];
        // Wholly behind the piece's owner (ties go to the owner), or not under it.
        if (piece.end <= from || piece.begin >= to || piece.bound * (1.0 + kTieTolerance) < near ||
            piece.owner == index) {
            push(piece);
            continue;
        }
        changed = true;
        split(piece, index, std::max(piece.begin, from), std::min(piece.end, to));
    }
    if (!changed) return;
    pieces_.erase(pieces_.begin() + std::ptrdiff_t(first), pieces_.begin() + std::ptrdiff_t(last));
    pieces_.insert(pieces_.begin() + std::ptrdiff_t(first), scratch_.begin(), scratch_.end());
}

void AngularEnvelope::split(const Piece& piece, int index, double from, double to) {
    const AngularShape& shape = shapes_[size_t(index)];
    const AngularExtent& extent = extents_[size_t(index)];
    const double bound = std::min(extent.max_distance, frame_.far);
    if (from > piece.begin) push({piece.begin, from, piece.owner, piece.tied, piece.bound});

    events_.clear();
    events_.push_back(from);
    events_.push_back(to);
    silhouetteEvents(shape, extent, frame_, from, to, events_);
    farEvents(shape, frame_, from, to, events_);
    const AngularShape* owner = nullptr;
    if (piece.owner >= 0) {
        owner = &shapes_[size_t(piece.owner)];
        silhouetteEvents(*owner, extents_[size_t(piece.owner)], frame_, from, to, events_);
        crossingEvents(*owner, shape, frame_, from, to, events_);
    }
    std::sort(events_.begin(), events_.end());

    double begin = from;
    for (size_t k = 1; k < events_.size(); ++k) {
        const double end = events_[k];
        if (!(end > begin)) continue;
        Piece next{begin, end, piece.owner, piece.tied, piece.bound};
        if (end - begin >= kMinPieceWidth) {
            const glm::dvec3 dir = frame_.direction(0.5 * (begin + end));
            ++rays_;
            const double d = rayDistance(shape, frame_, dir);
            const double d_owner = owner ? rayDistance(*owner, frame_, dir) : kInfinity;
            if (d < kInfinity && d_owner < kInfinity && sameDistance(d, d_owner)) {
                if (next.tied < 0) next.tied = index;  // the owner keeps the piece
            } else if (d < d_owner) {
                next = {begin, end, index, -1, bound};
            }
        }
        push(next);
        begin = end;
    }
    if (to < piece.end) push({to, piece.end, piece.owner, piece.tied, piece.bound});
}

void AngularEnvelope::markVisible(std::vector<char>& seen) const {
    // Owners of pieces narrower than kMinPieceWidth are not counted: such a piece is
    // a rounding of a single angle. A wider span of one owner is merged first.
    for (size_t i = 0; i < pieces_.size();) {
        const int32_t owner = pieces_[i].owner;
        double width = 0.0;
        size_t j = i;
        for (; j < pieces_.size() && pieces_[j].owner == owner; ++j)
            width += pieces_[j].end - pieces_[j].begin;
        if (owner >= 0 && width >= kMinPieceWidth) {
            assert(size_t(owner) < seen.size());
            seen[size_t(owner)] = 1;
        }
        i = j;
    }
    // A tied object is seen where it shares the owner's surface over a whole piece.
    for (const Piece& piece : pieces_) {
        if (piece.tied < 0 || piece.end - piece.begin < kMinPieceWidth) continue;
        assert(size_t(piece.tied) < seen.size());
        seen[size_t(piece.tied)] = 1;
    }
}

}  // namespace gridcull
