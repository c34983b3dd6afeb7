// frame.accum_frame on a real executor (lavapipe under the validation layer): it counts frames
// while nothing the picture depends on changes, and restarts at 0 when a param (the panel), the
// orbit camera, the view size (a resize rebuild) or a named camera changes; a reload that changes
// none of them keeps counting. tests/graphs/accumulation averages frames with it.
#include "exec/executor.hpp"

#include <gtest/gtest.h>

using namespace pl;
using namespace pl::exec;

namespace {

struct Lab {
    std::unique_ptr<vk::Context> ctx;
    std::unique_ptr<Executor> ex;
    int frame = 0;
    graph::OrbitCamera camera;

    std::unique_ptr<Executor> build(const std::string& graph, std::optional<std::array<int, 2>> size = {}) {
        BuildOptions bo;
        bo.size = size;
        auto built = build_graph(std::string(PASSLAB_TEST_DIR) + "/graphs/" + graph + "/preset.toml", bo);
        EXPECT_TRUE(built) << built.error().format();
        auto e = Executor::create(*ctx, std::move(built.value()));
        EXPECT_TRUE(e) << e.error().format();
        return std::move(e.value());
    }
    // Renders one frame; returns (mean, accum_frame as the shader saw it).
    std::pair<float, float> render() {
        FrameInput in;
        in.index = frame++;
        in.camera = camera;
        auto s = ex->render(in);
        EXPECT_TRUE(s) << s.error().format();
        auto img = ex->read("accum");
        EXPECT_TRUE(img);
        return {img->pixels[0], img->pixels[1]};
    }
};

Result<std::unique_ptr<vk::Context>> context() {
    vk::ContextOptions co;
    co.validation = true;
    co.verbose = false;
    return vk::Context::create(co);
}

} // namespace

TEST(Accumulation, ResetsWhenAParamTheCameraOrTheSizeChanges) {
    auto ctx = context();
    if (!ctx) GTEST_SKIP() << "no Vulkan device: " << ctx.error().message;
    Lab lab{std::move(ctx.value())};
    lab.ex = lab.build("accumulation");
    lab.camera = lab.ex->graph().desc.view.orbit;

    EXPECT_EQ(lab.render(), (std::pair{0.0f, 0.0f}));
    EXPECT_EQ(lab.render(), (std::pair{0.5f, 1.0f}));
    EXPECT_EQ(lab.render(), (std::pair{1.0f, 2.0f}));  // mean of 0, 1, 2
    EXPECT_EQ(lab.ex->accum_frame(), 2);

    // The panel moves a param: the average restarts from this frame's sample (3 + 10).
    lab.ex->params()[0].value[0] = 10.0;
    EXPECT_EQ(lab.render(), (std::pair{13.0f, 0.0f}));
    EXPECT_EQ(lab.render(), (std::pair{13.5f, 1.0f}));

    // Dragging the orbit camera restarts it too; holding still counts on.
    lab.camera.yaw += 5.0f;
    EXPECT_EQ(lab.render().second, 0.0f);
    EXPECT_EQ(lab.render().second, 1.0f);

    // A reload (a shader or comment edit) at the same size keeps counting ...
    auto same = lab.build("accumulation");
    same->params() = lab.ex->params();
    ASSERT_TRUE(same->adopt_contents(*lab.ex));
    lab.ex = std::move(same);
    EXPECT_EQ(lab.render().second, 2.0f);
    // ... a resize does not.
    auto resized = lab.build("accumulation", std::array<int, 2>{8, 8});
    resized->params() = lab.ex->params();
    ASSERT_TRUE(resized->adopt_contents(*lab.ex));
    lab.ex = std::move(resized);
    EXPECT_EQ(lab.render().second, 0.0f);
    EXPECT_EQ(lab.ctx->validation_message_count(), 0u);
}

TEST(Accumulation, ANamedCameraFollowingAParamResetsIt) {
    auto ctx = context();
    if (!ctx) GTEST_SKIP() << "no Vulkan device: " << ctx.error().message;
    Lab lab{std::move(ctx.value())};
    lab.ex = lab.build("cameras");
    lab.camera = lab.ex->graph().desc.view.orbit;
    auto step = [&] {
        FrameInput in;
        in.index = lab.frame++;
        in.camera = lab.camera;
        EXPECT_TRUE(lab.ex->render(in));
        return lab.ex->accum_frame();
    };
    EXPECT_EQ(step(), 0);
    EXPECT_EQ(step(), 1);
    // sun's eye is params.sun_dir * 10: the camera entries change with the param.
    auto& p = lab.ex->params()[0];
    ASSERT_EQ(p.name, "sun_dir");
    p.value[1] = 1.5;
    EXPECT_EQ(step(), 0);
    EXPECT_EQ(lab.ex->camera_entries()[0].position.y, 15.0f);
    EXPECT_EQ(step(), 1);
    // A value the camera cannot take (its eye on the target) keeps the last good camera.
    p.value[1] = 0.0;
    EXPECT_EQ(step(), 0);
    EXPECT_NE(lab.ex->camera_error().find("camera 'sun': target is the eye"), std::string::npos) << lab.ex->camera_error();
    EXPECT_EQ(lab.ex->camera_entries()[0].position.y, 15.0f);
    p.value[1] = 1.0;
    step();
    EXPECT_TRUE(lab.ex->camera_error().empty());
    EXPECT_EQ(lab.ctx->validation_message_count(), 0u);
}
