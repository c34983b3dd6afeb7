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
