// Graphviz output: nodes for passes and resources, edges for reads and writes.
#include "graph/dot.hpp"
#include "graph/parse.hpp"

#include <gtest/gtest.h>

#include <filesystem>

using namespace pl;
using namespace pl::graph;

namespace {

bool has(const std::string& s, const std::string& part) { return s.find(part) != std::string::npos; }

const char* kGraph = R"([preset]
title = "Dot \"test\""

[images]
hdr = { format = "rgba16f" }
depth = { format = "d32" }
acc = { format = "rgba32f", history = true }
ldr = {}
msaa = { samples = 4 }

[buffers]
args = { size = 16 }

[[pass]]
name = "scene"
kind = "draw"
vertex = "test/quad.vert"
vertex_count = 3
targets = [{ image = "msaa", resolve = "hdr" }]
depth = { image = "depth", test = "less", write = true }
indirect = "args"

[[pass]]
name = "accumulate"
fragment = "debug/uv.frag"
targets = ["acc"]

[[pass]]
name = "copy"
kind = "blit"
src = "acc"
dst = "ldr"
enabled = false

[output]
image = "ldr"
)";

} // namespace

TEST(Dot, NodesAndDescriptionEdges) {
    auto g = parse_graph_text(kGraph, "t/preset.toml");
    ASSERT_TRUE(g) << g.error().format();
    std::string dot = to_dot(*g, nullptr);
    EXPECT_EQ(dot.rfind("digraph \"Dot \\\"test\\\"\" {", 0), 0u) << dot;  // quotes escaped
    EXPECT_EQ(dot.back(), '\n');
    EXPECT_TRUE(has(dot, "\"pass:scene\" [shape=box")) << dot;
    EXPECT_TRUE(has(dot, "\"hdr\" [shape=ellipse")) << dot;
    EXPECT_TRUE(has(dot, "\"args\" [shape=ellipse")) << dot;           // buffers are ellipses too
    EXPECT_TRUE(has(dot, "\"acc\" [shape=ellipse, label=\"acc\\nrgba32f view\", style=dashed")) << dot;  // history
    EXPECT_TRUE(has(dot, "\"ldr\" [shape=ellipse, label=\"ldr\\nrgba8 view\", peripheries=2")) << dot;  // the output
    EXPECT_TRUE(has(dot, "\"pass:scene\" -> \"msaa\";"));               // target: write
    EXPECT_TRUE(has(dot, "\"pass:scene\" -> \"hdr\";"));                // resolve: write
    EXPECT_TRUE(has(dot, "\"pass:scene\" -> \"depth\";"));              // depth write
    EXPECT_TRUE(has(dot, "\"depth\" -> \"pass:scene\";"));              // depth test reads
    EXPECT_TRUE(has(dot, "\"args\" -> \"pass:scene\";"));               // indirect arguments
    EXPECT_TRUE(has(dot, "\"pass:accumulate\" -> \"acc\";"));
    EXPECT_TRUE(has(dot, "\"acc\" -> \"pass:copy\";"));                 // blit src
    EXPECT_TRUE(has(dot, "\"pass:copy\" -> \"ldr\";"));                 // blit dst
    EXPECT_TRUE(has(dot, "\"pass:copy\" [shape=box, label=\"copy\\nblit\", style=dashed")) << dot;  // disabled
    EXPECT_FALSE(has(dot, "\"hdr\" -> \"pass:accumulate\""));  // no shader reads without io
}

TEST(Dot, ShaderReadsAndWritesFromReflection) {
    auto g = parse_graph_text(kGraph, "t/preset.toml");
    ASSERT_TRUE(g);
    std::vector<PassIO> io(3);
    io[1].reads = {"hdr", "acc_prev", "unknown"};
    io[1].writes = {"acc"};
    std::string dot = to_dot(*g, &io);
    EXPECT_TRUE(has(dot, "\"hdr\" -> \"pass:accumulate\";")) << dot;
    EXPECT_TRUE(has(dot, "\"acc\" -> \"pass:accumulate\" [style=dashed, label=\"prev\"];")) << dot;  // last frame
    EXPECT_FALSE(has(dot, "unknown"));  // names the graph does not declare are not drawn
    // Each edge once, even when the description and reflection both report it.
    size_t first = dot.find("\"pass:accumulate\" -> \"acc\";");
    ASSERT_NE(first, std::string::npos);
    EXPECT_EQ(dot.find("\"pass:accumulate\" -> \"acc\";", first + 1), std::string::npos);
}

TEST(Dot, GroupIsAClusterAroundItsMembers) {
    std::string text = std::string(kGraph) + R"(
[[group]]
name = "twice"
repeat = 2
passes = ["accumulate", "scene"]
)";
    auto g = parse_graph_text(text, "t/preset.toml");
    ASSERT_TRUE(g) << g.error().format();
    std::string dot = to_dot(*g, nullptr);
    EXPECT_TRUE(has(dot, "subgraph \"cluster_group_twice\"")) << dot;
    EXPECT_TRUE(has(dot, "label=\"group twice, repeat 2: accumulate, scene\"")) << dot;
    EXPECT_TRUE(has(dot, "    \"pass:accumulate\";\n    \"pass:scene\";\n  }")) << dot;
}
