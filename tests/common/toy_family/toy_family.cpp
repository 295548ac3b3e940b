#include "tests/common/toy_family/toy_family.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>
#include <vector>

#include <imgui.h>
#include <glm/geometric.hpp>

#include "culling/registry/registry.h"
#include "ui/registry/family_views.h"

namespace gridcull::test {

namespace {

// --- The culling side: culling/toy/ in a real family. -------------------------

struct ToyOptions {
    int count = 5;  // objects kept
};

const KnobTable<ToyOptions>& toyKnobs() {
    static const KnobTable<ToyOptions> table{
        knob("toy-count", &ToyOptions::count, 1, 1000,
             "objects kept, the nearest to the camera first; more: a larger PVS"),
    };
    return table;
}

struct ToySnapshot final : DebugSnapshot {
    static const DebugSnapshotKind kKind;
    ToySnapshot() : DebugSnapshot(kKind) {}
    bool valid = false;
    glm::dvec3 eye{0.0};
    std::vector<std::pair<double, int>> kept;  // (distance, object index), nearest first
};
const DebugSnapshotKind ToySnapshot::kKind{"toy"};

class ToyCuller final : public Culler {
public:
    explicit ToyCuller(const ToyOptions& options) : options_(options) {}
    const char* name() const override { return "toy-nearest"; }
    void reset(const Scene& scene) override { order_.reserve(scene.objects.size()); }
    void cull(const Scene& scene, const Camera& camera, double t, FrameResult& out) override {
        out.stats = CullStats{};
        out.pvs.clear();
        order_.clear();
        for (size_t i = 0; i < scene.objects.size(); ++i) {
            const glm::dvec3 anchor = scene.positionAt(scene.objects[i].id, t);
            order_.push_back({glm::length(anchor - camera.position), int(i)});
        }
        const size_t kept = std::min(order_.size(), size_t(std::max(options_.count, 0)));
        std::partial_sort(order_.begin(), order_.begin() + std::ptrdiff_t(kept), order_.end());
        order_.resize(kept);
        for (const auto& [distance, index] : order_)
            out.pvs.push_back(scene.objects[size_t(index)].id);
        std::sort(out.pvs.begin(), out.pvs.end());
        out.stats.set(Counter::ObjectsTested, int64_t(scene.objects.size()));
        snapshot_.valid = capture_;
        if (capture_) {
            snapshot_.eye = camera.position;
            snapshot_.kept = order_;
        }
    }
    void setDebugCapture(bool on) override { capture_ = on; }
    const DebugSnapshot* debugSnapshot() const override {
        return snapshot_.valid ? &snapshot_ : nullptr;
    }

private:
    ToyOptions options_;
    std::vector<std::pair<double, int>> order_;
    bool capture_ = false;
    ToySnapshot snapshot_;
};

FamilyEntry toyFamily() {
    FamilyEntry family;
    family.id = "toy";
    family.title = "Toy family (tests only)";
    family.algorithms = {{"toy-nearest", kRunsBoth, "the nearest --toy-count objects (a test)"}};
    family.knobs = toyKnobs().knobs();
    family.make = [](CullerRequest& request) -> std::unique_ptr<Culler> {
        return std::make_unique<ToyCuller>(toyKnobs().read(*request.knobs));
    };
    return family;
}

// --- The window side: ui/toy/ in a real family. -------------------------------

struct ToyViewFlags {
    int label = 1;  // 1: label the kept objects with their ids
};

const KnobTable<ToyViewFlags>& toyViewFlags() {
    static const KnobTable<ToyViewFlags> table{
        knob("toy-labels", &ToyViewFlags::label, 0, 1, "1: label each kept object"),
    };
    return table;
}

class ToyView final : public FamilyView {
public:
    bool applyFlags(const KnobValues& flags, const Scene&, std::string&) override {
        labels_ = toyViewFlags().read(flags).label != 0;
        return true;
    }

    void drawPanel(const FamilyViewContext& context, FamilyAction& action) override {
        const ToySnapshot* toy = snapshotOf(context);
        if (!toy ||
            !ImGui::CollapsingHeader("Toy family (tests only)", ImGuiTreeNodeFlags_DefaultOpen))
            return;
        ImGui::Text("kept %zu nearest of %zu objects", toy->kept.size(),
                    context.scene->objects.size());
        for (const auto& [distance, index] : toy->kept)
            ImGui::Text("  object %d at %.2f", context.scene->objects[size_t(index)].id, distance);
        int count = int(toy->kept.size());
        ImGui::SetNextItemWidth(-1.0f);
        ImGui::SliderInt("##toy count", &count, 1, 20, "toy-count %d");
        if (ImGui::IsItemDeactivatedAfterEdit()) action.knobs.emplace_back("toy-count", count);
    }

    void drawOverlay(const FamilyViewContext& context, const OverlayView& view,
                     DebugDraw& draw) override {
        const ToySnapshot* toy = snapshotOf(context);
        if (!toy || toy->kept.empty()) return;
        const Scene& scene = *context.scene;
        // World space: the kept objects' voxels, a line from the eye to each, their
        // bounds as a filled polygon with a dashed box around it, and labels.
        glm::dvec3 lo(1e300), hi(-1e300);
        for (const auto& [distance, index] : toy->kept) {
            const glm::dvec3 p = scene.positionAt(scene.objects[size_t(index)].id, context.t);
            lo = glm::min(lo, p);
            hi = glm::max(hi, p);
            if (scene.dimensions == 2) {
                const glm::ivec3 v = scene.grid.voxelOf(p);
                draw.fillVoxel(scene.grid, v.x, v.y, {Swatch::BluishGreen, 0.6f});
            }
            draw.line(DrawSpace::World, toy->eye, p, {Swatch::Yellow, 0.8f}, kBoldLine);
        }
        const glm::dvec3 corners[4] = {
            {lo.x, lo.y, 0}, {hi.x, lo.y, 0}, {hi.x, hi.y, 0}, {lo.x, hi.y, 0}};
        draw.fillConvexPolygon(DrawSpace::World, corners, 4, {Swatch::Orange, 0.15f});
        draw.outlinePolygon(DrawSpace::World, corners, 4, {Swatch::Orange}, kFineLine);
        draw.dashedRect(DrawSpace::World, lo.x - 2, lo.y - 2, hi.x + 2, hi.y + 2, {Swatch::White},
                        kHairline, 1.5, 1.0);
        if (labels_) {
            // Beside the voxel, not over it.
            const glm::dvec3 offset(1.5 * scene.grid.voxelSize().x, 0.0, 0.0);
            for (const auto& [distance, index] : toy->kept) {
                char text[32];
                std::snprintf(text, sizeof text, "#%d", scene.objects[size_t(index)].id);
                draw.text(DrawSpace::World,
                          scene.positionAt(scene.objects[size_t(index)].id, context.t) + offset,
                          text, {Swatch::White});
            }
        }
        // View space: a key in the top-left corner: a rectangle, hatched, and one
        // cell per kept object laid out as a 1-row image over it.
        const ViewRect key{12.0, 12.0, 12.0 + 40.0 * double(toy->kept.size()), 52.0};
        draw.fillRect(key, {Swatch::NearBlack, 0.7f});
        draw.hatchRect(DrawSpace::View, key.x0, key.y0, key.x1, key.y1, {Swatch::Grey, 0.5f},
                       kHairline, 6.0);
        ImageFrame cells;
        cells.area = key;
        cells.image_width = int(toy->kept.size());
        cells.image_height = 1;
        for (int k = 0; k < cells.image_width; ++k) {
            const ViewRect r = cells.pixelsToView(PixelRect{k, 0, k, 0});
            draw.outlineRect({r.x0 + 3, r.y0 + 3, r.x1 - 3, r.y1 - 3}, {Swatch::SkyBlue},
                             kBoldLine);
        }
        draw.outlineRect(key, {Swatch::White}, kHeavyLine);
        draw.text(DrawSpace::View, {key.x0, key.y1 + 6.0, 0.0}, "toy-nearest", {Swatch::Yellow});
        (void)view;
    }

private:
    static const ToySnapshot* snapshotOf(const FamilyViewContext& context) {
        const ToySnapshot* toy = context.snapshot ? context.snapshot->as<ToySnapshot>() : nullptr;
        return toy && toy->valid ? toy : nullptr;
    }
    bool labels_ = true;
};

FamilyViewEntry toyFamilyView() {
    FamilyViewEntry entry;
    entry.family = "toy";
    entry.flags = toyViewFlags().knobs();
    entry.make = [] { return std::make_unique<ToyView>(); };
    return entry;
}

}  // namespace

bool registerToyFamily(std::string& error) {
    if (findFamily("toy") && findFamilyView("toy")) return true;
    if (!findFamily("toy") && !registerFamily(toyFamily(), error)) return false;
    return findFamilyView("toy") || registerFamilyView(toyFamilyView(), error);
}

void unregisterToyFamily() {
    unregisterFamilyView("toy");
    unregisterFamily("toy");
}

}  // namespace gridcull::test
