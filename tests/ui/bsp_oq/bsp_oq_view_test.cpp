// The bsp family in the window: the session's snapshot, the colours, masks and
// node pick of ui/bsp_oq/bsp_oq_view.h, the World-space node boxes and the
// View-space query rectangles (ui/bsp_oq/bsp_oq_overlay.h) as the debug-draw
// batch records them, and the family's view from the ui registry: its flags,
// the pointer (hover on a node gives its history), redraws that allocate
// nothing, and the panel column drawn headless. On the moving bunnies
// (Kovalčík & Sochor's Figure 5 scene), from inside the box.
#include <algorithm>
#include <cfloat>
#include <cmath>
#include <set>
#include <string>

#include <gtest/gtest.h>
#include <imgui.h>

#include "culling/bsp_oq/bsp_oq_snapshot.h"
#include "culling/io/scene_loader.h"
#include "culling/registry/registry.h"
#include "tests/ui/headless_imgui.h"
#include "tests/common/allocation_counter.h"
#include "tests/ui/panel_test_helpers.h"
#include "ui/bsp_oq/bsp_oq_overlay.h"
#include "ui/bsp_oq/bsp_oq_view.h"
#include "ui/debugger_session.h"
#include "ui/registry/family_views.h"

namespace gridcull {
namespace {

constexpr int kFrame = 120;  // t = 4.8: inside the box, looking along it
constexpr int kSmallImage = 160;
constexpr int kViewWidth = 900, kViewHeight = 720;
constexpr size_t kBoxVertices = 24;  // 12 edges, 2 vertices each

Scene loadScene(const char* name) {
    SceneLoadResult loaded = loadSceneFile(std::string(GRIDCULL_SOURCE_DIR) + "/scenes/" + name);
    EXPECT_TRUE(loaded.scene) << name;
    return loaded.scene ? std::move(*loaded.scene) : Scene{};
}

KnobValues smallImage() {
    KnobValues knobs;
    knobs.set("oracle-res", kSmallImage);
    return knobs;
}

const BspOqSnapshot* bspOf(const DebuggerSession& session) {
    const DebugSnapshot* s = session.debugSnapshot();
    return s ? s->as<BspOqSnapshot>() : nullptr;
}

BspOqViewState only(int mask, bool queries = false) {
    BspOqViewState view;
    setBspNodeMask(view, mask);
    view.show_queries = queries;
    return view;
}

bool sameColor(const glm::vec4& c, Swatch s) {
    const Rgb rgb = swatchColor(s);
    return std::abs(c.r - rgb.r) < 1e-6f && std::abs(c.g - rgb.g) < 1e-6f &&
           std::abs(c.b - rgb.b) < 1e-6f;
}

std::vector<DebugDrawBatch::Vertex> allLines(const DebugDrawBatch& batch, DrawSpace space) {
    std::vector<DebugDrawBatch::Vertex> out;
    for (const DebugDrawBatch::LineSet& set : batch.layer(space).lines)
        out.insert(out.end(), set.vertices.begin(), set.vertices.end());
    return out;
}

size_t lineCount(const DebugDrawBatch& batch, DrawSpace space) {
    return allLines(batch, space).size();
}

// Culling 120 frames of 300 bunnies takes seconds: every test reads one session.
DebuggerSession& bunniesAtFrame() {
    static DebuggerSession* session = [] {
        auto* s = new DebuggerSession(smallImage());
        std::string error;
        EXPECT_TRUE(s->open(loadScene("bunnies-3d.json"), "", "bsp-oq", error)) << error;
        s->seek(kFrame);
        return s;
    }();
    return *session;
}

class BspOqViewTest : public ::testing::Test {
protected:
    void SetUp() override {
        snap_ = bspOf(session_);
        ASSERT_NE(snap_, nullptr);
        ASSERT_EQ(session_.frame(), kFrame);
    }

    const std::vector<DebugDrawBatch::Vertex>& lines(DrawSpace space, float width) const {
        static const std::vector<DebugDrawBatch::Vertex> none;
        for (const DebugDrawBatch::LineSet& set : batch_.layer(space).lines)
            if (set.width == width) return set.vertices;
        return none;
    }
    // An object whose tree the traversal entered this frame, -1: none.
    int enteredTree() const {
        for (size_t i = 0; i < snap_->object_first.size(); ++i)
            if (snap_->object_first[i] >= 0) return int(i);
        return -1;
    }
    ImageFrame frame() const {
        return cullingImageFrame(session_.cullingCamera().aspect, kViewWidth, kViewHeight,
                                 snap_->width, snap_->height);
    }

    const DebuggerSession& session_ = bunniesAtFrame();
    const BspOqSnapshot* snap_ = nullptr;
    DebugDrawBatch batch_;
};

TEST_F(BspOqViewTest, SessionExposesTheSnapshotOfBspCullersOnly) {
    EXPECT_STREQ(session_.debugSnapshot()->kind().family, "bsp");
    EXPECT_EQ(snap_->mode, BspOqMode::Full);
    EXPECT_FALSE(snap_->queries.empty()) << "inside the box, bsp-oq queries nodes";
    EXPECT_GT(snap_->state_count[size_t(BspNodeState::QueriedHidden)], 0);
    EXPECT_GT(snap_->state_count[size_t(BspNodeState::AssumedVisible)], 0)
        << "after 120 frames coherence skips queries";
    EXPECT_GE(enteredTree(), 0) << "every bunny has a tree; some is entered";
    // The other modes, and another family, early in the flight (cheap).
    DebuggerSession session(smallImage());
    std::string error;
    ASSERT_TRUE(session.open(loadScene("bunnies-3d.json"), "", "bsp-oq-simple", error)) << error;
    session.seek(2);
    for (const char* algo : {"bsp-oq-simple", "bsp-vfc"}) {
        ASSERT_TRUE(session.selectAlgorithm(algo, error)) << error;
        const BspOqSnapshot* s = bspOf(session);
        ASSERT_NE(s, nullptr) << algo;
        EXPECT_EQ(s->mode, std::string(algo) == "bsp-vfc" ? BspOqMode::Vfc : BspOqMode::Simple);
    }
    ASSERT_TRUE(session.selectAlgorithm("vfc", error)) << error;
    EXPECT_EQ(bspOf(session), nullptr);
}

// One meaning per colour: every state its own swatch, none an object state's
// or the camera's; the query rectangles take their answer's state colour.
TEST(BspOqColours, EachStateItsOwnColourAndTheQueriesTheirAnswers) {
    std::set<Swatch> seen;
    for (int k = 0; k < kBspNodeStateCount; ++k) {
        const Swatch s = bspNodeStateSwatch(BspNodeState(k));
        EXPECT_TRUE(seen.insert(s).second) << bspNodeStateName(BspNodeState(k));
        for (Swatch taken : {Swatch::Blue, Swatch::SkyBlue, Swatch::Vermillion, Swatch::Yellow})
            EXPECT_NE(s, taken) << bspNodeStateName(BspNodeState(k));
        EXPECT_STRNE(bspNodeStateMeaning(BspNodeState(k)), "");
    }
    EXPECT_EQ(bspQuerySwatch(true), bspNodeStateSwatch(BspNodeState::QueriedVisible));
    EXPECT_EQ(bspQuerySwatch(false), bspNodeStateSwatch(BspNodeState::QueriedHidden));
    BspOqViewState view;
    EXPECT_EQ(bspNodeMask(view), 8 | 16 | 32 | 64 | 128) << "the decided states by default";
    setBspNodeMask(view, 2 | 64);
    for (int k = 0; k < kBspNodeStateCount; ++k) EXPECT_EQ(view.show_nodes[k], k == 1 || k == 6);
}

// Each state shown alone: one wire box per scene node in that state, on the box
// it was tested on, in the colour the panel's key gives the state.
TEST_F(BspOqViewTest, OverlayDrawsTheSceneNodesOfTheStatesShownInTheirKeyColour) {
    int states_with_nodes = 0;
    for (int k = 0; k < kBspNodeStateCount; ++k) {
        const auto state = BspNodeState(k);
        std::vector<const BspNodeRecord*> nodes;
        for (const BspNodeRecord& n : snap_->scene_nodes)
            if (n.state == state) nodes.push_back(&n);
        batch_.clear();
        const BspOverlayCounts counts = drawBspOqNodes(*snap_, only(1 << k), -1, {}, batch_);
        const size_t n = std::min(nodes.size(), size_t(kBspMaxNodesDrawn));
        EXPECT_EQ(counts.scene_nodes, int(n)) << bspNodeStateName(state);
        const std::vector<DebugDrawBatch::Vertex> set = allLines(batch_, DrawSpace::World);
        ASSERT_EQ(set.size(), kBoxVertices * n) << bspNodeStateName(state);
        EXPECT_EQ(lines(DrawSpace::World, bspNodeStateWidth(state)).size(), set.size());
        for (size_t b = 0; b < n; ++b) {
            glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
            for (size_t v = kBoxVertices * b; v < kBoxVertices * (b + 1); ++v) {
                EXPECT_TRUE(sameColor(set[v].color, bspNodeStateSwatch(state)));
                lo = glm::min(lo, set[v].position);
                hi = glm::max(hi, set[v].position);
            }
            for (int a = 0; a < 3; ++a) {
                EXPECT_NEAR(lo[a], nodes[b]->box.min[a], 1e-3);
                EXPECT_NEAR(hi[a], nodes[b]->box.max[a], 1e-3);
            }
        }
        states_with_nodes += n > 0 ? 1 : 0;
    }
    EXPECT_GE(states_with_nodes, 4);
    batch_.clear();
    EXPECT_EQ(drawBspOqNodes(*snap_, only(0), -1, {}, batch_).scene_nodes, 0);
    EXPECT_TRUE(batch_.empty());
}

// A picked object's tree: its nodes the same way, after the scene tree's.
TEST_F(BspOqViewTest, OverlayDrawsThePickedObjectsTree) {
    const int object = enteredTree();
    ASSERT_GE(object, 0);
    const int first = snap_->object_first[size_t(object)];
    const int count = snap_->object_count[size_t(object)];
    ASSERT_GT(count, 1);
    const BspOverlayCounts scene_only = drawBspOqNodes(*snap_, only(255), -1, {}, batch_);
    const size_t scene_vertices = lineCount(batch_, DrawSpace::World);
    batch_.clear();
    const BspOverlayCounts counts = drawBspOqNodes(*snap_, only(255), object, {}, batch_);
    EXPECT_EQ(counts.scene_nodes, scene_only.scene_nodes);
    EXPECT_EQ(counts.object_nodes, std::min(count, kBspMaxNodesDrawn));
    EXPECT_EQ(lineCount(batch_, DrawSpace::World),
              scene_vertices + kBoxVertices * size_t(counts.object_nodes));
    for (int k = first; k < first + count; ++k)
        EXPECT_EQ(snap_->object_nodes[size_t(k)].object, object);
    // An object with no entered tree (-1, or out of range) draws none.
    EXPECT_EQ(bspShownTree(*snap_, -1), -1);
    EXPECT_EQ(bspShownTree(*snap_, 1 << 20), -1);
}

// The query rectangles: one per query of the batches shown, where ImageFrame
// puts its pixels, coloured by answer, labelled with its batch.
TEST_F(BspOqViewTest, QueryRectanglesByAnswerAndBatch) {
    ASSERT_GE(snap_->batch_count, 2) << "bsp-oq batches its queries";
    const ImageFrame f = frame();
    BspOqViewState view = only(0, true);
    const BspOverlayCounts all = drawBspOqQueries(*snap_, view, f, batch_);
    size_t expected = 0;
    for (const BspQueryRecord& q : snap_->queries) expected += q.rect.empty() ? 0 : 1;
    EXPECT_EQ(all.queries, int(expected));
    EXPECT_GT(all.labels, 0);
    EXPECT_TRUE(batch_.layer(DrawSpace::World).lines.empty()) << "View space only";
    const std::vector<DebugDrawBatch::Vertex>& set = lines(DrawSpace::View, kBspQueryWidth);
    ASSERT_EQ(set.size(), 8 * expected);  // four sides, two vertices each
    size_t r = 0;
    for (const BspQueryRecord& q : snap_->queries) {
        if (q.rect.empty()) continue;
        const ViewRect v = f.pixelsToView(q.rect);
        glm::vec3 lo(FLT_MAX), hi(-FLT_MAX);
        for (size_t k = 8 * r; k < 8 * (r + 1); ++k) {
            EXPECT_TRUE(sameColor(set[k].color, bspQuerySwatch(q.visible)));
            lo = glm::min(lo, set[k].position);
            hi = glm::max(hi, set[k].position);
        }
        EXPECT_NEAR(lo.x, v.x0, 1e-3);
        EXPECT_NEAR(hi.y, v.y1, 1e-3);
        ++r;
    }
    for (const DebugDrawBatch::Label& label : batch_.layer(DrawSpace::View).labels) {
        const int b = std::stoi(batch_.labelText(label));
        EXPECT_GE(b, 0);
        EXPECT_LT(b, snap_->batch_count);
    }

    // One batch: its queries only, every label its number.
    view.batch = 1;
    batch_.clear();
    const BspOverlayCounts one = drawBspOqQueries(*snap_, view, f, batch_);
    int in_batch = 0;
    for (const BspQueryRecord& q : snap_->queries) in_batch += q.batch == 1 && !q.rect.empty();
    EXPECT_EQ(one.queries, in_batch);
    EXPECT_LT(one.queries, all.queries);
    for (const DebugDrawBatch::Label& label : batch_.layer(DrawSpace::View).labels)
        EXPECT_EQ(batch_.labelText(label), "1");

    view.show_queries = false;
    batch_.clear();
    EXPECT_EQ(drawBspOqQueries(*snap_, view, f, batch_).queries, 0);
    EXPECT_TRUE(batch_.empty());
}

// The hover pick on a hand-made snapshot: a box around the eye is skipped, the
// first box entered wins, a tie the smaller box; the node's answers read
// latest first.
TEST(BspOqPick, FirstBoxEnteredAndItsHistory) {
    BspOqSnapshot s;
    s.valid = true;
    auto node = [&](Aabb box, int depth, BspNodeState state) {
        BspNodeRecord r;
        r.box = r.cell = box;
        r.node = int32_t(s.scene_nodes.size());
        r.depth = depth;
        r.state = state;
        s.scene_nodes.push_back(r);
    };
    node({{-100, -100, -100}, {100, 100, 100}}, 0, BspNodeState::ViewerInside);  // the eye's
    node({{10, -1, -1}, {14, 1, 1}}, 1, BspNodeState::QueriedVisible);
    node({{10, -1, -1}, {12, 1, 1}}, 2, BspNodeState::QueriedVisible);  // same front face
    node({{5, 5, 5}, {6, 6, 6}}, 1, BspNodeState::QueriedHidden);      // off the ray
    node({{20, -1, -1}, {22, 1, 1}}, 1, BspNodeState::QueriedHidden);  // behind
    s.scene_nodes[2].history = 0b1101;  // latest visible, then hidden, visible, visible
    s.scene_nodes[2].history_length = 5;
    BspOqViewState view = only(255);
    const glm::dvec3 eye(0.0), along_x(1.0, 0.0, 0.0);
    BspNodeRef ref = pickBspNode(s, view, -1, eye, along_x);
    EXPECT_EQ(ref, (BspNodeRef{2, false}));
    char marks[kMaxBspHistory + 1];
    bspHistoryMarks(*bspNodeOf(s, ref), marks);
    EXPECT_STREQ(marks, "VHVVH");
    // Hidden states not shown: the pick sees only what is drawn.
    view.show_nodes[int(BspNodeState::QueriedVisible)] = false;
    EXPECT_EQ(pickBspNode(s, view, -1, eye, along_x), (BspNodeRef{4, false}));
    EXPECT_FALSE(pickBspNode(s, view, -1, eye, -along_x).valid());
    bspHistoryMarks(s.scene_nodes[0], marks);
    EXPECT_STREQ(marks, "") << "never queried";
}

// The window redraws the overlay every frame: redrawing it (every state, a
// picked object's tree, a picked node, the rectangles) allocates nothing.
TEST_F(BspOqViewTest, RedrawingTheOverlayAllocatesNothing) {
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("bsp-oq")->make();
    KnobValues flags;
    flags.set("bsp-object", session_.scene().objects[size_t(enteredTree())].id);
    flags.set("bsp-show-nodes", 255);
    flags.set("bsp-node", snap_->scene_nodes.back().node);
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    FamilyViewContext context;
    context.scene = &session_.scene();
    context.algo = "bsp-oq";
    context.snapshot = snap_;
    OverlayView overlay;
    overlay.width = kViewWidth;
    overlay.height = kViewHeight;
    overlay.through_culling_camera = true;
    overlay.culling_aspect = session_.cullingCamera().aspect;
    view->drawOverlay(context, overlay, batch_);
    ASSERT_FALSE(batch_.empty());
    test::startCounting();
    for (int k = 0; k < 2; ++k) {
        batch_.clear();
        view->drawOverlay(context, overlay, batch_);
    }
    test::stopCounting();
    EXPECT_EQ(test::allocationCount(), 0);
}

class BspOqPanelTest : public BspOqViewTest {
protected:
    void SetUp() override {
        BspOqViewTest::SetUp();
        test::createHeadlessImGui();
        names_ = algorithmNames(3);
        snapshot_ = test::snapshotOfSession(session_, names_, file_, errors_);
        snapshot_.algo_index =
            int(std::find(names_.begin(), names_.end(), "bsp-oq") - names_.begin());
        context_.scene = &session_.scene();
        context_.algo = "bsp-oq";
        context_.snapshot = snap_;
        overlay_.width = kViewWidth;
        overlay_.height = kViewHeight;
        overlay_.through_culling_camera = true;
        overlay_.culling_aspect = session_.cullingCamera().aspect;
    }
    void TearDown() override { ImGui::DestroyContext(); }

    void redraw(FamilyView& view) {
        batch_.clear();
        view.drawOverlay(context_, overlay_, batch_);
    }

    std::vector<std::string> names_;
    const std::string file_;
    const std::vector<std::string> errors_;
    FrameSnapshot snapshot_;
    FamilyViewContext context_;
    OverlayView overlay_;
};

// The family's view from the ui registry: every flag changes what is drawn.
TEST_F(BspOqPanelTest, EachFlagChangesWhatIsDrawn) {
    const FamilyViewEntry* entry = familyViewOfAlgorithm("bsp-oq-simple");
    ASSERT_NE(entry, nullptr);
    EXPECT_EQ(entry->family, "bsp");
    for (const char* flag :
         {"bsp-show-nodes", "bsp-show-queries", "bsp-show-batch", "bsp-object", "bsp-node"})
        EXPECT_EQ(familyViewOfFlag(flag), entry) << flag;
    std::unique_ptr<FamilyView> view = entry->make();
    KnobValues flags;
    std::string error;
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    const size_t world_default = lineCount(batch_, DrawSpace::World);
    const size_t view_default = lineCount(batch_, DrawSpace::View);
    EXPECT_GT(world_default, 0u);
    EXPECT_GT(view_default, 0u) << "the query rectangles";

    // --bsp-show-nodes: 0 none; 255 more than the default.
    flags.set("bsp-show-nodes", 0);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    EXPECT_EQ(lineCount(batch_, DrawSpace::World), 0u);
    flags.set("bsp-show-nodes", 255);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    const size_t world_all = lineCount(batch_, DrawSpace::World);
    EXPECT_GT(world_all, world_default);

    // --bsp-object: the bunny's tree on top of the scene tree's boxes.
    const int object = enteredTree();
    flags.set("bsp-object", session_.scene().objects[size_t(object)].id);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    EXPECT_EQ(view->focusedObject(context_), object);
    redraw(*view);
    EXPECT_EQ(lineCount(batch_, DrawSpace::World),
              world_all + kBoxVertices * size_t(std::min(snap_->object_count[size_t(object)],
                                                          kBspMaxNodesDrawn)));

    // --bsp-node: the node again, heavy.
    EXPECT_TRUE(lines(DrawSpace::World, kBspFocusWidth).empty());
    flags.set("bsp-node", snap_->scene_nodes.front().node);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    EXPECT_EQ(lines(DrawSpace::World, kBspFocusWidth).size(), kBoxVertices);

    // --bsp-show-batch 0: the first batch's rectangles only.
    flags.set("bsp-show-batch", 0);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    const size_t view_batch0 = lineCount(batch_, DrawSpace::View);
    EXPECT_GT(view_batch0, 0u);
    EXPECT_LT(view_batch0, view_default);

    // --bsp-show-queries 0: none; and none in a view not through the culling camera.
    flags.set("bsp-show-queries", 0);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    redraw(*view);
    EXPECT_EQ(lineCount(batch_, DrawSpace::View), 0u);
    flags.set("bsp-show-queries", 1);
    ASSERT_TRUE(view->applyFlags(flags, session_.scene(), error)) << error;
    overlay_.through_culling_camera = false;
    redraw(*view);
    EXPECT_EQ(lineCount(batch_, DrawSpace::View), 0u);

    // Another snapshot kind, or none: nothing.
    context_.snapshot = nullptr;
    redraw(*view);
    EXPECT_TRUE(batch_.empty());

    flags.set("bsp-object", 999999);
    EXPECT_FALSE(view->applyFlags(flags, session_.scene(), error));
    EXPECT_NE(error.find("--bsp-object 999999"), std::string::npos) << error;
}

// Hover: the pointer over a queried node's box focuses it (heavy box, panel
// rows with its answers); a click keeps it after the pointer leaves.
TEST_F(BspOqPanelTest, HoverOnANodeGivesItsHistory) {
    std::unique_ptr<FamilyView> view = familyViewOfAlgorithm("bsp-oq")->make();
    const int base = test::familyPanelVertices(snapshot_, view.get(), context_);
    EXPECT_GT(base, 1000);
    const glm::dvec3 eye = session_.cullingCamera().position;
    // The node: a queried one with answers, whose box the ray from the eye to
    // its centre enters before any other drawn box.
    BspNodeRef target;
    ViewPointer pointer;
    pointer.over_view = true;
    pointer.origin = eye;
    BspOqViewState view_state;
    for (size_t i = 0; i < snap_->scene_nodes.size() && !target.valid(); ++i) {
        const BspNodeRecord& n = snap_->scene_nodes[i];
        if (n.history_length < 2 || !view_state.shown(n.state) || n.box.contains(eye)) continue;
        const glm::dvec3 dir = glm::normalize(n.box.center() - eye);
        if (pickBspNode(*snap_, view_state, -1, eye, dir) == BspNodeRef{int32_t(i), false}) {
            target = {int32_t(i), false};
            pointer.direction = dir;
        }
    }
    ASSERT_TRUE(target.valid()) << "some queried node is in front under some ray";
    const BspNodeRecord& node = *bspNodeOf(*snap_, target);
    char marks[kMaxBspHistory + 1];
    bspHistoryMarks(node, marks);
    EXPECT_EQ(std::string(marks).size(), size_t(std::min(node.history_length, kMaxBspHistory)));
    EXPECT_EQ(marks[0] == 'V', bool(node.history & 1u)) << "the latest answer first";

    view->pointer(context_, pointer);
    redraw(*view);
    const std::vector<DebugDrawBatch::Vertex>& heavy = lines(DrawSpace::World, kBspFocusWidth);
    ASSERT_EQ(heavy.size(), kBoxVertices) << "the hovered node, heavy";
    EXPECT_TRUE(sameColor(heavy[0].color, bspNodeStateSwatch(node.state)));
    glm::vec3 lo(FLT_MAX);
    for (const DebugDrawBatch::Vertex& v : heavy) lo = glm::min(lo, v.position);
    EXPECT_NEAR(lo.x, node.box.min.x, 1e-3);
    // The panel grows by the node's rows, one mark per answer.
    EXPECT_GT(test::familyPanelVertices(snapshot_, view.get(), context_), base);

    // Leaving the view drops the hover; a click before it keeps the node.
    ViewPointer away;
    view->pointer(context_, away);
    redraw(*view);
    EXPECT_TRUE(lines(DrawSpace::World, kBspFocusWidth).empty());
    pointer.clicked = true;
    view->pointer(context_, pointer);
    view->pointer(context_, away);
    redraw(*view);
    EXPECT_EQ(lines(DrawSpace::World, kBspFocusWidth).size(), kBoxVertices) << "picked";
}

}  // namespace
}  // namespace gridcull
