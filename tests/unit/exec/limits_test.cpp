// Buffer bindings against device limits: the check runs on the compiled graph (no GPU), so the
// limits can be those of any device, here smaller than this graph's buffers.
#include "exec/build.hpp"
#include "exec/limits.hpp"

#include <gtest/gtest.h>

using namespace pl::exec;

namespace {

CompiledGraph build() {
    auto g = build_graph(std::filesystem::path(PASSLAB_TEST_DIR) / "unit/exec/data/limits/preset.toml", {});
    if (!g) ADD_FAILURE() << g.error().format();
    return std::move(g.value());
}

const std::map<std::string, VkDeviceSize> kSizes = {{"table", 1024}, {"items", 4096}};

} // namespace

TEST(BindingLimits, WithinLimitsPasses) {
    VkPhysicalDeviceLimits lim{};
    lim.maxUniformBufferRange = 1024;  // exactly the size: allowed
    lim.maxStorageBufferRange = 4096;
    EXPECT_TRUE(check_binding_limits(lim, "Test GPU", build(), kSizes));
}

TEST(BindingLimits, StorageBufferOverLimitNamesSizeKeyLimitAndDevice) {
    VkPhysicalDeviceLimits lim{};
    lim.maxUniformBufferRange = 65536;
    lim.maxStorageBufferRange = 4095;
    auto s = check_binding_limits(lim, "Test GPU", build(), kSizes);
    ASSERT_FALSE(s);
    const pl::Error& e = s.error();
    EXPECT_EQ(e.resource, "items");
    EXPECT_EQ(e.pass, "main");
    EXPECT_EQ(e.loc.line, 7);   // the `size` value of `items`
    EXPECT_EQ(e.loc.col, 18);
    EXPECT_NE(e.message.find("maxStorageBufferRange = 4095"), std::string::npos) << e.message;
    EXPECT_NE(e.message.find("Test GPU"), std::string::npos) << e.message;
}

TEST(BindingLimits, UniformBufferOverLimitSuggestsStorage) {
    VkPhysicalDeviceLimits lim{};
    lim.maxUniformBufferRange = 512;
    lim.maxStorageBufferRange = 1u << 27;
    auto s = check_binding_limits(lim, "Test GPU", build(), kSizes);
    ASSERT_FALSE(s);
    EXPECT_EQ(s.error().resource, "table");
    EXPECT_NE(s.error().message.find("maxUniformBufferRange = 512"), std::string::npos) << s.error().message;
    EXPECT_NE(s.error().hint.find("storage"), std::string::npos);
}
