// The `rooms` generator after Sudarsky & Gotsman's test scene: a building of
// square rooms joined by doors, a table per room and chairs circling the tables
// (layout and sizes in scene_generators.h), and optionally people walking from
// room to room through the doors (the paper's Fig. 13a building with moving men).
#include <algorithm>
#include <cmath>

#include <glm/vec2.hpp>

#include "culling/generators/scene_emitter.h"
#include "culling/generators/scene_generators.h"
#include "culling/scene/scene_limits.h"
#include "culling/scene/seeded_random.h"

namespace gridcull {

namespace {

// Floor-plan axes: x and z in 3D (y is up), x and y in 2D.
struct Plan {
    int a = 0, b = 2;
    bool is_3d = true;
    double ground = 0.0;

    // A box over [a0, a1] x [b0, b1] on the floor plan, `height` tall in 3D.
    Aabb box(double a0, double a1, double b0, double b1, double height) const {
        Aabb r;
        r.min[a] = a0;
        r.max[a] = a1;
        r.min[b] = b0;
        r.max[b] = b1;
        if (is_3d) {
            r.min.y = ground;
            r.max.y = ground + height;
        }
        return r;
    }
};

using RoomsEmitter = SceneEmitter;

// A point on the square loop of half-size `half` around `centre`, at arc
// length `u` (any real; the loop has length 8 * half) counter-clockwise from
// the corner (-half, -half).
glm::dvec2 onLoop(const glm::dvec2& centre, double half, double u) {
    const double side = 2.0 * half;
    double w = std::fmod(u, 4.0 * side);
    if (w < 0.0) w += 4.0 * side;
    const int k = std::min(3, int(w / side));
    const double f = w - double(k) * side;
    switch (k) {
        case 0:
            return centre + glm::dvec2(-half + f, -half);
        case 1:
            return centre + glm::dvec2(half, -half + f);
        case 2:
            return centre + glm::dvec2(half - f, half);
        default:
            return centre + glm::dvec2(-half, half - f);
    }
}

// The four doors of a room, as a step to the neighbouring room and the arc
// length on the walkway (onLoop) of the middle of the side facing the door.
struct Door {
    int di, dj;
    double u_in_q;  // arc length / q
};
constexpr Door kDoors[4] = {{0, -1, 1.0}, {1, 0, 3.0}, {0, 1, 5.0}, {-1, 0, 7.0}};

// People walking from room to room (scene_generators.h, "rooms"): keyframes
// along each room's walkway and straight through the door gaps.
void generatePeople(const RoomsParams& p, const Plan& plan, double a0, double b0, int64_t max_keys,
                    double duration, SeededRandom& rng, RoomsEmitter& out) {
    const double s = p.room_size, t = p.wall_thickness;
    const double half_w = 0.5 * kPersonWidth * s, height = kPersonHeight * s;
    const double inner_face = 0.5 * s - 0.5 * t, table_half = 0.15 * s;
    const double lo = table_half + half_w, hi = inner_face - half_w;
    const double q = lo + 0.75 * (hi - lo);  // the walkway's half-size
    const double loop = 8.0 * q, side = 2.0 * q, eps = 1e-9 * q;
    const double speed = p.people_speed;
    const int64_t i_min = p.people_room_min[0], j_min = p.people_room_min[1];
    const int64_t i_max = p.people_room_max[0] < 0 ? p.rooms_x - 1 : p.people_room_max[0];
    const int64_t j_max = p.people_room_max[1] < 0 ? p.rooms_z - 1 : p.people_room_max[1];
    const int64_t span_i = i_max - i_min + 1, span_j = j_max - j_min + 1;
    auto centre_of = [&](int64_t i, int64_t j) {
        return glm::dvec2{a0 + (double(i) + 0.5) * s, b0 + (double(j) + 0.5) * s};
    };
    auto in_region = [&](int64_t i, int64_t j) {
        return i >= i_min && i <= i_max && j >= j_min && j <= j_max;
    };
    auto wrap = [&](double u) {
        double w = std::fmod(u, loop);
        if (w < 0.0) w += loop;
        return w;
    };
    for (int64_t n = 0; n < p.people; ++n) {
        int64_t i = i_min + int64_t(rng.below(uint64_t(span_i)));
        int64_t j = j_min + int64_t(rng.below(uint64_t(span_j)));
        double u = rng.uniform(0.0, loop);
        glm::dvec2 centre = centre_of(i, j);
        const glm::dvec2 start = onLoop(centre, q, u);
        SceneObject person;
        person.shape = ShapeKind::Box;
        person.box = plan.box(start.x - half_w, start.x + half_w, start.y - half_w,
                              start.y + half_w, height);
        if (speed > 0.0) {
            person.motion.kind = MotionKind::Keyframes;
            const double anchor_height = plan.is_3d ? plan.ground + 0.5 * height : 0.0;
            double time = 0.0;
            auto full = [&] { return int64_t(person.motion.keys.size()) >= max_keys; };
            auto key_at = [&](const glm::dvec2& q2) {
                PositionKey pk;
                pk.t = time;
                pk.position[plan.a] = q2.x;
                pk.position[plan.b] = q2.y;
                if (plan.is_3d) pk.position.y = anchor_height;
                person.motion.keys.push_back(pk);
            };
            key_at(start);
            // Along the walkway by `distance` (> 0) in `direction` (+1: counter-
            // clockwise), a key at each corner passed and at the end.
            auto walk = [&](double distance, double direction) {
                while (distance > eps && !full() && time < duration) {
                    const double next_corner = direction > 0.0
                                                   ? (std::floor((u + eps) / side) + 1.0) * side
                                                   : (std::ceil((u - eps) / side) - 1.0) * side;
                    const double step = std::min(distance, std::abs(next_corner - u));
                    const double next_time = time + step / speed;
                    if (!(next_time > time)) break;  // keys must stay strictly increasing
                    u += direction * step;
                    distance -= step;
                    time = next_time;
                    key_at(onLoop(centre, q, u));
                }
                u = wrap(u);
            };
            int came_through = -1;  // the door (index in kDoors) into this room
            while (!full() && time < duration) {
                int choices[4];
                int count = 0;
                for (int d = 0; d < 4; ++d)
                    if (in_region(i + kDoors[d].di, j + kDoors[d].dj)) choices[count++] = d;
                if (count == 0) {  // a single room: round the walkway
                    walk(side, 1.0);
                    continue;
                }
                if (count > 1 && came_through >= 0) {  // not back the way it came
                    const int back = (came_through + 2) % 4;
                    count = int(std::remove(choices, choices + count, back) - choices);
                }
                const int d = choices[rng.below(uint64_t(count))];
                const double ccw = wrap(kDoors[d].u_in_q * q - u);
                if (ccw > eps && loop - ccw > eps) {
                    const bool go_ccw =
                        ccw < loop - ccw - eps ||
                        (std::abs(ccw - (loop - ccw)) <= eps && rng.uniform() < 0.5);
                    walk(go_ccw ? ccw : loop - ccw, go_ccw ? 1.0 : -1.0);
                }
                if (full() || time >= duration) break;
                // Through the door, to the middle of the facing side next door.
                const double next_time = time + (s - 2.0 * q) / speed;
                if (!(next_time > time)) break;
                time = next_time;
                i += kDoors[d].di;
                j += kDoors[d].dj;
                centre = centre_of(i, j);
                came_through = d;
                u = kDoors[(d + 2) % 4].u_in_q * q;
                key_at(onLoop(centre, q, u));
            }
            person.motion.max_speed = keyframeSpeed(person.motion.keys);
        }
        out.add(std::move(person));
    }
}

}  // namespace

void generateRooms(const RoomsParams& p, SeededRandom& rng, Scene& scene, int& next_id) {
    const Aabb& world = scene.grid.world;
    Plan plan;
    plan.is_3d = scene.dimensions == 3;
    plan.b = plan.is_3d ? 2 : 1;
    plan.ground = p.has_ground ? p.ground : world.min.y;
    RoomsEmitter out{scene, next_id};
    const double s = p.room_size, t = p.wall_thickness, door = p.door_width;
    const double wall_height = 0.3 * s;
    const double a0 = world.center()[plan.a] - double(p.rooms_x) * s * 0.5;
    const double b0 = world.center()[plan.b] - double(p.rooms_z) * s * 0.5;

    // Walls on lines of constant a (running along b), then of constant b. A wall
    // between two rooms has a door in the middle; outer walls are closed.
    for (int64_t i = 0; i <= p.rooms_x; ++i) {
        const double at = a0 + double(i) * s;
        const bool inner = i > 0 && i < p.rooms_x;
        for (int64_t j = 0; j < p.rooms_z; ++j) {
            const double start = b0 + double(j) * s - t * 0.5, end = start + s + t;
            const double mid = b0 + (double(j) + 0.5) * s;
            if (inner) {
                out.addBox(
                    plan.box(at - t * 0.5, at + t * 0.5, start, mid - door * 0.5, wall_height));
                out.addBox(
                    plan.box(at - t * 0.5, at + t * 0.5, mid + door * 0.5, end, wall_height));
            } else {
                out.addBox(plan.box(at - t * 0.5, at + t * 0.5, start, end, wall_height));
            }
        }
    }
    for (int64_t j = 0; j <= p.rooms_z; ++j) {
        const double at = b0 + double(j) * s;
        const bool inner = j > 0 && j < p.rooms_z;
        for (int64_t i = 0; i < p.rooms_x; ++i) {
            const double start = a0 + double(i) * s - t * 0.5, end = start + s + t;
            const double mid = a0 + (double(i) + 0.5) * s;
            if (inner) {
                out.addBox(
                    plan.box(start, mid - door * 0.5, at - t * 0.5, at + t * 0.5, wall_height));
                out.addBox(
                    plan.box(mid + door * 0.5, end, at - t * 0.5, at + t * 0.5, wall_height));
            } else {
                out.addBox(plan.box(start, end, at - t * 0.5, at + t * 0.5, wall_height));
            }
        }
    }

    if (p.ceiling && plan.is_3d) {
        Aabb slab = plan.box(a0 - t * 0.5, a0 + double(p.rooms_x) * s + t * 0.5, b0 - t * 0.5,
                             b0 + double(p.rooms_z) * s + t * 0.5, wall_height + t);
        slab.min.y = plan.ground + wall_height;
        out.addBox(slab);
    }

    // Chairs circle the table halfway between its edge and the walls' inner
    // faces; with wall_thickness < room_size / 2 they touch neither.
    const double table_half = 0.15 * s, chair_half = 0.025 * s, chair_height = 0.1 * s;
    const double loop_half = (table_half + 0.5 * s - 0.5 * t) * 0.5;
    const double duration = scene.frames * scene.dt;
    // Chairs and people share the key budget.
    const int64_t movers = p.rooms_x * p.rooms_z * p.chairs_per_room + p.people;
    const int64_t max_keys = std::clamp<int64_t>(
        movers > 0 ? kMaxRandomSegments / movers : kMaxChairKeys, 2, kMaxChairKeys);
    for (int64_t j = 0; j < p.rooms_z; ++j) {
        for (int64_t i = 0; i < p.rooms_x; ++i) {
            const glm::dvec2 centre{a0 + (double(i) + 0.5) * s, b0 + (double(j) + 0.5) * s};
            out.addBox(plan.box(centre.x - table_half, centre.x + table_half, centre.y - table_half,
                                centre.y + table_half, 0.075 * s));
            for (int64_t k = 0; k < p.chairs_per_room; ++k) {
                const double u0 = rng.uniform(0.0, 8.0 * loop_half);
                const double direction = rng.uniform() < 0.5 ? -1.0 : 1.0;
                const glm::dvec2 start = onLoop(centre, loop_half, u0);
                SceneObject chair;
                chair.shape = ShapeKind::Box;
                chair.box = plan.box(start.x - chair_half, start.x + chair_half,
                                     start.y - chair_half, start.y + chair_half, chair_height);
                if (p.chair_speed > 0.0) {
                    // Keys at the start and at every corner the chair passes, until
                    // the scene ends or the key budget is spent.
                    chair.motion.kind = MotionKind::Keyframes;
                    const double anchor_height =
                        plan.is_3d ? plan.ground + 0.5 * chair_height : 0.0;
                    auto key = [&](double time, double u) {
                        const glm::dvec2 q = onLoop(centre, loop_half, u);
                        PositionKey pk;
                        pk.t = time;
                        pk.position[plan.a] = q.x;
                        pk.position[plan.b] = q.y;
                        if (plan.is_3d) pk.position.y = anchor_height;
                        chair.motion.keys.push_back(pk);
                    };
                    key(0.0, u0);
                    const double side = 2.0 * loop_half;
                    double corner = direction > 0.0 ? (std::floor(u0 / side) + 1.0) * side
                                                    : std::ceil(u0 / side - 1.0) * side;
                    double time = std::abs(corner - u0) / p.chair_speed;
                    while (int64_t(chair.motion.keys.size()) < max_keys) {
                        if (time > 0.0) key(time, corner);
                        if (time >= duration) break;
                        corner += direction * side;
                        const double next = time + side / p.chair_speed;
                        if (!(next > time)) break;  // keys must stay strictly increasing
                        time = next;
                    }
                    chair.motion.max_speed = keyframeSpeed(chair.motion.keys);
                }
                out.add(std::move(chair));
            }
        }
    }

    if (p.people > 0) generatePeople(p, plan, a0, b0, max_keys, duration, rng, out);
}

}  // namespace gridcull
