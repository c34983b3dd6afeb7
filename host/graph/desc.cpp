// Look-ups over the graph description. Linear searches: graphs have tens of entries, and the
// vectors keep declaration order (UI order, std140 order) which a map would lose.
#include "graph/desc.hpp"

namespace pl::graph {

namespace {
template <class V> auto* find_named(const V& v, const std::string& n) {
    for (const auto& x : v)
        if (x.name == n) return &x;
    return static_cast<const typename V::value_type*>(nullptr);
}
} // namespace

SourceLoc KeyLocs::at(const std::string& key, const SourceLoc& fallback) const {
    auto it = map.find(key);
    return it != map.end() && it->second.known() ? it->second : fallback;
}

const ImageDesc* GraphDesc::find_image(const std::string& n) const { return find_named(images, n); }
const BufferDesc* GraphDesc::find_buffer(const std::string& n) const { return find_named(buffers, n); }
const MeshDesc* GraphDesc::find_mesh(const std::string& n) const { return find_named(meshes, n); }
const ParamDesc* GraphDesc::find_param(const std::string& n) const { return find_named(params, n); }
const PassDesc* GraphDesc::find_pass(const std::string& n) const { return find_named(passes, n); }
const CameraDesc* GraphDesc::find_camera(const std::string& n) const { return find_named(cameras, n); }

const GroupDesc* GraphDesc::group_of(const std::string& n) const {
    for (const auto& gr : groups)
        for (const auto& p : gr.passes)
            if (p == n) return &gr;
    return nullptr;
}

int ParamDesc::components() const {
    switch (type) {
    case ParamType::vec2: return 2;
    case ParamType::vec3:
    case ParamType::color3: return 3;
    case ParamType::vec4:
    case ParamType::color4: return 4;
    case ParamType::f32:
    case ParamType::i32:
    case ParamType::boolean:
    case ParamType::enumeration: return 1;
    }
    return 1;
}

const char* kind_name(PassKind k) {
    switch (k) {
    case PassKind::fullscreen: return "fullscreen";
    case PassKind::draw: return "draw";
    case PassKind::compute: return "compute";
    case PassKind::blit: return "blit";
    case PassKind::mips: return "mips";
    case PassKind::clear: return "clear";
    case PassKind::copy: return "copy";
    }
    return "?";
}

} // namespace pl::graph
