// The planner derives every barrier and layout transition; these tests pin the rules down
// without a GPU.
#include "exec/plan.hpp"

#include <gtest/gtest.h>

using namespace pl::exec;

namespace {
constexpr VkPipelineStageFlags2 kFrag = VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
constexpr VkPipelineStageFlags2 kComp = VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
} // namespace

TEST(Transition, FirstUseAsTargetTransitionsFromUndefined) {
    ResourceState s;
    auto b = transition(s, usage_of(Access::color_attachment, 0));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->old_layout, VK_IMAGE_LAYOUT_UNDEFINED);
    EXPECT_EQ(b->new_layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(s.layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

TEST(Transition, RenderThenSampleMakesWritesVisibleToFragmentShader) {
    ResourceState s;
    transition(s, usage_of(Access::color_attachment, 0));
    auto b = transition(s, usage_of(Access::sampled, kFrag));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->old_layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(b->new_layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
    EXPECT_EQ(b->src_stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(b->src_access, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
    EXPECT_EQ(b->dst_stages, kFrag);
    EXPECT_EQ(b->dst_access, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT);
}

TEST(Transition, SecondReadInSameLayoutNeedsNoBarrier) {
    ResourceState s;
    transition(s, usage_of(Access::color_attachment, 0));
    ASSERT_TRUE(transition(s, usage_of(Access::sampled, kFrag)));
    EXPECT_FALSE(transition(s, usage_of(Access::sampled, kFrag)));
}

TEST(Transition, ReadFromANewStageAfterWriteNeedsBarrier) {
    ResourceState s;
    transition(s, usage_of(Access::storage_write, kComp));
    ASSERT_TRUE(transition(s, usage_of(Access::storage_read, kComp)));
    // The fragment stage has not been made to see the compute write yet.
    auto b = transition(s, usage_of(Access::storage_read, kFrag));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->src_stages, kComp);
    EXPECT_EQ(b->dst_stages, kFrag);
}

TEST(Transition, WriteAfterReadWaitsForTheReaders) {
    ResourceState s;
    transition(s, usage_of(Access::color_attachment, 0));
    transition(s, usage_of(Access::sampled, kFrag));
    auto b = transition(s, usage_of(Access::color_attachment, 0));
    ASSERT_TRUE(b);
    EXPECT_TRUE(b->src_stages & kFrag);  // readers must finish before the overwrite
    EXPECT_EQ(b->new_layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
}

TEST(Transition, WriteAfterWriteInGeneralLayoutStillBarriers) {
    ResourceState s;
    transition(s, usage_of(Access::storage_read_write, kComp));
    auto b = transition(s, usage_of(Access::storage_read_write, kComp));
    ASSERT_TRUE(b);
    EXPECT_EQ(b->old_layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_EQ(b->new_layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_TRUE(b->src_access & VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT);
}

TEST(Transition, DiscardDropsOldContents) {
    ResourceState s;
    transition(s, usage_of(Access::sampled, kFrag));
    auto b = transition(s, usage_of(Access::transfer_dst, 0), true);
    ASSERT_TRUE(b);
    EXPECT_EQ(b->old_layout, VK_IMAGE_LAYOUT_UNDEFINED);
}

TEST(Merge, SampledAndStorageInOnePassIsGeneral) {
    Usage u = merge(usage_of(Access::sampled, kFrag), usage_of(Access::storage_write, kFrag));
    EXPECT_EQ(u.layout, VK_IMAGE_LAYOUT_GENERAL);
    EXPECT_TRUE(u.write);
}

TEST(Order, FileOrderIsKeptWithoutDependencies) {
    std::vector<PlanPass> p = {{"a", {}, {}, {"x"}}, {"b", {}, {}, {"y"}}, {"c", {}, {}, {"z"}}};
    auto o = order_passes(p);
    ASSERT_TRUE(o);
    EXPECT_EQ(*o, (std::vector<size_t>{0, 1, 2}));
}

TEST(Order, WriterDeclaredLaterMovesBeforeReader) {
    std::vector<PlanPass> p = {{"shade", {}, {"gbuf"}, {"hdr"}}, {"geometry", {}, {}, {"gbuf"}}};
    auto o = order_passes(p);
    ASSERT_TRUE(o);
    EXPECT_EQ(*o, (std::vector<size_t>{1, 0}));
}

TEST(Order, ReaderWaitsForLastEarlierWriterAndBlocksLaterWriter) {
    std::vector<PlanPass> p = {
        {"w1", {}, {}, {"x"}}, {"r", {}, {"x"}, {"y"}}, {"w2", {}, {}, {"x"}}};
    auto o = order_passes(p);
    ASSERT_TRUE(o);
    EXPECT_EQ(*o, (std::vector<size_t>{0, 1, 2}));
}

TEST(Order, ReadModifyWritePassesKeepFileOrder) {
    // Two draws that both add to a counter (atomics: read and write) and both draw into one
    // colour target: the first counter user is its first writer, not a reader waiting for the
    // second; no cycle, file order.
    std::vector<PlanPass> p = {{"first", {}, {"count", "color"}, {"count", "color"}},
                               {"second", {}, {"count", "color"}, {"count", "color"}},
                               {"show", {}, {"count"}, {"out"}}};
    auto o = order_passes(p);
    ASSERT_TRUE(o) << o.error().format();
    EXPECT_EQ(*o, (std::vector<size_t>{0, 1, 2}));
}

TEST(Order, CycleIsNamedWithPassesAndResources) {
    pl::SourceLoc la{"g.toml", 3, 1}, lb{"g.toml", 9, 1};
    std::vector<PlanPass> p = {{"a", la, {"y"}, {"x"}}, {"b", lb, {"x"}, {"y"}}};
    // a reads y written only later by b, b reads x written by a: a -> b -> a.
    auto o = order_passes(p);
    ASSERT_FALSE(o);
    std::string msg = o.error().format();
    EXPECT_NE(msg.find("cycle"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'a'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'b'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'x'"), std::string::npos) << msg;
    EXPECT_NE(msg.find("'y'"), std::string::npos) << msg;
    EXPECT_EQ(o.error().loc.line > 0, true);
}

TEST(Order, SelfReadWriteIsNotACycle) {
    std::vector<PlanPass> p = {{"jacobi", {}, {"a", "b"}, {"a", "b"}}};
    EXPECT_TRUE(order_passes(p));
}

// Per-subresource state: a reduction reads level i and writes level i + 1 of one image.

TEST(SubresourceTransition, ImageInOneStateGetsOneBarrierOverTheRange) {
    ImageState s(10, 1);
    auto bs = transition(s, s.all(), usage_of(Access::sampled, kFrag));
    ASSERT_EQ(bs.size(), 1u);  // UNDEFINED -> SHADER_READ_ONLY for all 10 levels at once
    EXPECT_EQ(bs[0].range, (SubRange{0, 10, 0, 1}));
    EXPECT_TRUE(transition(s, s.all(), usage_of(Access::sampled, kFrag)).empty());  // nothing changes
}

TEST(SubresourceTransition, ReadLevelIWriteLevelIPlusOneTouchesOnlyThoseLevels) {
    ImageState s(4, 1);
    transition(s, s.all(), usage_of(Access::sampled, kFrag));
    // Iteration 0: level 1 becomes a target; level 0 is already readable: one barrier.
    auto w = transition(s, {1, 1, 0, 1}, usage_of(Access::color_attachment, 0));
    ASSERT_EQ(w.size(), 1u);
    EXPECT_EQ(w[0].range, (SubRange{1, 1, 0, 1}));
    EXPECT_TRUE(transition(s, {0, 1, 0, 1}, usage_of(Access::sampled, kFrag)).empty());
    // Iteration 1: level 1 read (after its write: a barrier), level 2 written.
    auto r = transition(s, {1, 1, 0, 1}, usage_of(Access::sampled, kFrag));
    ASSERT_EQ(r.size(), 1u);
    EXPECT_EQ(r[0].barrier.old_layout, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL);
    EXPECT_EQ(r[0].barrier.src_stages, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT);
    EXPECT_EQ(s.at(3, 0).layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);  // untouched
    EXPECT_EQ(s.at(1, 0).layout, VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL);
}

TEST(SubresourceTransition, DifferingLevelsSplitIntoRectanglesAndEqualOnesMerge) {
    ImageState s(5, 2);
    transition(s, s.all(), usage_of(Access::sampled, kFrag));
    transition(s, {2, 1, 0, 2}, usage_of(Access::color_attachment, 0));  // level 2 written
    auto bs = transition(s, s.all(), usage_of(Access::transfer_src, 0));
    // Levels 0-1 (read), level 2 (written), levels 3-4 (read): three rectangles of 2 layers.
    ASSERT_EQ(bs.size(), 3u);
    EXPECT_EQ(bs[0].range, (SubRange{0, 2, 0, 2}));
    EXPECT_EQ(bs[1].range, (SubRange{2, 1, 0, 2}));
    EXPECT_EQ(bs[2].range, (SubRange{3, 2, 0, 2}));
    EXPECT_EQ(bs[1].barrier.src_access & VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT);
}

TEST(SubresourceTransition, OneLayerWrittenSplitsTheLayerRun) {
    ImageState s(1, 6);
    transition(s, s.all(), usage_of(Access::sampled, kFrag));
    transition(s, {0, 1, 3, 1}, usage_of(Access::color_attachment, 0));
    auto bs = transition(s, s.all(), usage_of(Access::sampled, kComp));
    // Layers 0-2 and 4-5 were only read: a read from another stage needs no barrier. Layer 3
    // was written: its write must be made visible to the compute stage.
    ASSERT_EQ(bs.size(), 1u);
    EXPECT_EQ(bs[0].range, (SubRange{0, 1, 3, 1}));
}

TEST(Order, AGroupIsNamedAsAGroupInACycle) {
    std::vector<PlanPass> p = {{"g", {}, {"y"}, {"x"}, true}, {"between", {}, {"x"}, {"y"}}};
    auto r = order_passes(p);
    ASSERT_FALSE(r);
    bool named = false;
    for (const auto& n : r.error().notes) named = named || n.find("from group 'g'") != std::string::npos;
    EXPECT_TRUE(named);
}
