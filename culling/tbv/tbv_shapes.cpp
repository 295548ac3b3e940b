// Shapes of temporal bounding volumes (Sudarsky & Gotsman, sections 3.2 and
// 3.3). tbv_shapes.h says where they depart from the paper.
#include "culling/tbv/tbv_shapes.h"

#include <cassert>
#include <cmath>

namespace gridcull {

namespace {

// The pad for a shape whose coordinates are of magnitude `scale`.
double padFor(double scale) {
    return kTbvRelativePad * std::max(scale, 1e-300);
}

double magnitude(int dimensions, const glm::dvec3& v) {
    double m = 0.0;
    for (int a = 0; a < dimensions; ++a) m = std::max(m, std::abs(v[a]));
    return m;
}

// How far an object at `speed` gets in `validity` seconds. A still object
// (speed 0) may have an infinite validity; a moving one needs a finite one.
double growth(double speed, double validity) {
    if (speed == 0.0) return 0.0;
    assert(std::isfinite(validity) && "a moving object's TBV needs a finite validity");
    return speed * validity;
}

bool validDimensions(int dimensions) {
    return dimensions == 2 || dimensions == 3;
}

double squaredDistance(int dimensions, const glm::dvec3& a, const glm::dvec3& b) {
    double d = 0.0;
    for (int i = 0; i < dimensions; ++i) d += (a[i] - b[i]) * (a[i] - b[i]);
    return d;
}

}  // namespace

const char* tbvShapeName(TbvShapeKind kind) {
    switch (kind) {
        case TbvShapeKind::Sphere:
            return "sphere";
        case TbvShapeKind::Box:
            return "box";
        case TbvShapeKind::Swept:
            return "swept";
    }
    return "?";
}

namespace tbv_detail {

TbvBox padded(int dimensions, const TbvBox& box) {
    double scale = 0.0;
    for (int a = 0; a < dimensions; ++a)
        scale =
            std::max({scale, box.max[a] - box.min[a], std::abs(box.min[a]), std::abs(box.max[a])});
    const double pad = padFor(scale);
    TbvBox out = box;
    for (int a = 0; a < dimensions; ++a) {
        out.min[a] -= pad;
        out.max[a] += pad;
    }
    return out;
}

}  // namespace tbv_detail

TbvShape sphereTbv(int dimensions, const glm::dvec3& position, double bounding_radius,
                   double max_speed, double validity) {
    assert(validDimensions(dimensions));
    assert(bounding_radius >= 0.0 && max_speed >= 0.0 && validity >= 0.0);
    TbvShape shape;
    shape.kind = TbvShapeKind::Sphere;
    shape.dimensions = dimensions;
    shape.centre = position;
    const double r = bounding_radius + growth(max_speed, validity);
    shape.radius = r + padFor(std::max(r, magnitude(dimensions, position)));
    shape.box = tbvBounds(shape);
    return shape;
}

TbvShape boxTbv(int dimensions, const TbvBox& object_box, double max_speed, double validity) {
    return boxTbv(dimensions, object_box, glm::dvec3(max_speed), validity);
}

TbvShape boxTbv(int dimensions, const TbvBox& object_box, const glm::dvec3& axis_speed,
                double validity) {
    assert(validDimensions(dimensions));
    assert(validity >= 0.0);
    TbvBox grown = object_box;
    for (int a = 0; a < dimensions; ++a) {
        assert(axis_speed[a] >= 0.0 && object_box.min[a] <= object_box.max[a]);
        grown.min[a] -= growth(axis_speed[a], validity);
        grown.max[a] += growth(axis_speed[a], validity);
    }
    TbvShape shape;
    shape.kind = TbvShapeKind::Box;
    shape.dimensions = dimensions;
    shape.box = tbv_detail::padded(dimensions, grown);
    shape.centre = (shape.box.min + shape.box.max) * 0.5;
    return shape;
}

TbvBox tbvBounds(const TbvShape& shape) {
    if (shape.kind != TbvShapeKind::Sphere) return shape.box;
    TbvBox box{shape.centre, shape.centre};
    for (int a = 0; a < shape.dimensions; ++a) {
        box.min[a] -= shape.radius;
        box.max[a] += shape.radius;
    }
    return box;
}

bool tbvContainsBox(const TbvShape& shape, const TbvBox& box) {
    const int dims = shape.dimensions;
    if (shape.kind != TbvShapeKind::Sphere) {
        for (int a = 0; a < dims; ++a)
            if (box.min[a] < shape.box.min[a] || box.max[a] > shape.box.max[a]) return false;
        return true;
    }
    // The corner farthest from the centre, axis by axis.
    double d = 0.0;
    for (int a = 0; a < dims; ++a) {
        const double far = std::max(std::abs(box.min[a] - shape.centre[a]),
                                    std::abs(box.max[a] - shape.centre[a]));
        d += far * far;
    }
    return d <= shape.radius * shape.radius;
}

bool tbvContainsBall(const TbvShape& shape, const glm::dvec3& centre, double radius) {
    assert(radius >= 0.0);
    if (shape.kind != TbvShapeKind::Sphere) {
        TbvBox ball{centre, centre};
        for (int a = 0; a < shape.dimensions; ++a) {
            ball.min[a] -= radius;
            ball.max[a] += radius;
        }
        return tbvContainsBox(shape, ball);
    }
    if (radius > shape.radius) return false;
    const double room = shape.radius - radius;
    return squaredDistance(shape.dimensions, centre, shape.centre) <= room * room;
}

}  // namespace gridcull
