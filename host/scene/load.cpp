// Mesh files: .obj through tinyobjloader, .gltf/.glb through tinygltf (Debian ships both as
// compiled libraries). Everything becomes one indexed triangle list in our Vertex layout.
#include "scene/mesh.hpp"

#include <tiny_gltf.h>
#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <map>
#include <tuple>

namespace fs = std::filesystem;

namespace pl::scene {

namespace {

void compute_normals(Mesh& m) {
    for (auto& v : m.vertices) v.normal[0] = v.normal[1] = v.normal[2] = 0.0f;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        Vertex* v[3] = {&m.vertices[m.indices[t]], &m.vertices[m.indices[t + 1]], &m.vertices[m.indices[t + 2]]};
        float e1[3], e2[3];
        for (int k = 0; k < 3; ++k) e1[k] = v[1]->position[k] - v[0]->position[k], e2[k] = v[2]->position[k] - v[0]->position[k];
        float n[3] = {e1[1] * e2[2] - e1[2] * e2[1], e1[2] * e2[0] - e1[0] * e2[2], e1[0] * e2[1] - e1[1] * e2[0]};
        for (auto* x : v)  // area-weighted: the cross product's length is twice the area
            for (int k = 0; k < 3; ++k) x->normal[k] += n[k];
    }
    for (auto& v : m.vertices) {
        float l = std::sqrt(v.normal[0] * v.normal[0] + v.normal[1] * v.normal[1] + v.normal[2] * v.normal[2]);
        if (l > 0) for (float& c : v.normal) c /= l;
        else v.normal[1] = 1.0f;
    }
}

Result<Mesh> load_obj(const fs::path& file) {
    tinyobj::ObjReaderConfig cfg;
    cfg.triangulate = true;
    cfg.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), cfg))
        return make_error("cannot load mesh '" + file.string() + "': " + reader.Error());
    const auto& attrib = reader.GetAttrib();
    Mesh m;
    bool has_normals = !attrib.normals.empty();
    std::map<std::tuple<int, int, int>, uint32_t> dedupe;
    for (const auto& shape : reader.GetShapes())
        for (const auto& idx : shape.mesh.indices) {
            auto key = std::make_tuple(idx.vertex_index, idx.normal_index, idx.texcoord_index);
            auto it = dedupe.find(key);
            if (it != dedupe.end()) {
                m.indices.push_back(it->second);
                continue;
            }
            if (idx.vertex_index < 0 || size_t(3 * idx.vertex_index + 2) >= attrib.vertices.size())
                return make_error("mesh '" + file.string() + "': a face refers to a vertex that does not exist");
            Vertex v{};
            for (int k = 0; k < 3; ++k) v.position[k] = attrib.vertices[3 * idx.vertex_index + k];
            if (idx.normal_index >= 0 && size_t(3 * idx.normal_index + 2) < attrib.normals.size())
                for (int k = 0; k < 3; ++k) v.normal[k] = attrib.normals[3 * idx.normal_index + k];
            if (idx.texcoord_index >= 0 && size_t(2 * idx.texcoord_index + 1) < attrib.texcoords.size()) {
                v.uv[0] = attrib.texcoords[2 * idx.texcoord_index];
                v.uv[1] = 1.0f - attrib.texcoords[2 * idx.texcoord_index + 1];  // OBJ v is bottom-up
            }
            uint32_t n = static_cast<uint32_t>(m.vertices.size());
            m.vertices.push_back(v);
            dedupe.emplace(key, n);
            m.indices.push_back(n);
        }
    if (m.indices.empty()) return make_error("mesh '" + file.string() + "' has no faces");
    if (!has_normals) compute_normals(m);
    return m;
}

// Reads accessor element `i` as up to 4 floats.
bool read_floats(const tinygltf::Model& model, const tinygltf::Accessor& acc, size_t i, float* out, int n) {
    if (acc.bufferView < 0 || acc.componentType != TINYGLTF_COMPONENT_TYPE_FLOAT) return false;
    const auto& view = model.bufferViews[static_cast<size_t>(acc.bufferView)];
    const auto& buf = model.buffers[static_cast<size_t>(view.buffer)];
    size_t stride = acc.ByteStride(view) > 0 ? static_cast<size_t>(acc.ByteStride(view)) : sizeof(float) * n;
    size_t off = view.byteOffset + acc.byteOffset + i * stride;
    if (off + sizeof(float) * n > buf.data.size()) return false;
    std::memcpy(out, &buf.data[off], sizeof(float) * n);
    return true;
}

Result<Mesh> load_gltf(const fs::path& file) {
    tinygltf::TinyGLTF loader;
    tinygltf::Model model;
    std::string err, warn;
    bool ok = file.extension() == ".glb" ? loader.LoadBinaryFromFile(&model, &err, &warn, file.string())
                                         : loader.LoadASCIIFromFile(&model, &err, &warn, file.string());
    if (!ok) return make_error("cannot load mesh '" + file.string() + "': " + (err.empty() ? warn : err));
    Mesh m;
    bool need_normals = false;
    for (const auto& mesh : model.meshes)
        for (const auto& prim : mesh.primitives) {
            if (prim.mode != TINYGLTF_MODE_TRIANGLES && prim.mode != -1) continue;
            auto pos = prim.attributes.find("POSITION");
            if (pos == prim.attributes.end()) continue;
            const auto& pacc = model.accessors[static_cast<size_t>(pos->second)];
            uint32_t base = static_cast<uint32_t>(m.vertices.size());
            auto nrm = prim.attributes.find("NORMAL");
            auto uv = prim.attributes.find("TEXCOORD_0");
            for (size_t i = 0; i < pacc.count; ++i) {
                Vertex v{};
                if (!read_floats(model, pacc, i, v.position, 3))
                    return make_error("mesh '" + file.string() + "': unreadable POSITION data");
                if (nrm != prim.attributes.end()) read_floats(model, model.accessors[static_cast<size_t>(nrm->second)], i, v.normal, 3);
                else need_normals = true;
                if (uv != prim.attributes.end()) read_floats(model, model.accessors[static_cast<size_t>(uv->second)], i, v.uv, 2);
                m.vertices.push_back(v);
            }
            if (prim.indices >= 0) {
                const auto& iacc = model.accessors[static_cast<size_t>(prim.indices)];
                const auto& view = model.bufferViews[static_cast<size_t>(iacc.bufferView)];
                const auto& buf = model.buffers[static_cast<size_t>(view.buffer)];
                size_t sz = tinygltf::GetComponentSizeInBytes(static_cast<uint32_t>(iacc.componentType));
                for (size_t i = 0; i < iacc.count; ++i) {
                    size_t off = view.byteOffset + iacc.byteOffset + i * sz;
                    if (off + sz > buf.data.size()) return make_error("mesh '" + file.string() + "': index data out of range");
                    uint32_t idx = 0;
                    std::memcpy(&idx, &buf.data[off], sz);
                    if (idx >= pacc.count) return make_error("mesh '" + file.string() + "': index out of range");
                    m.indices.push_back(base + idx);
                }
            } else {
                for (uint32_t i = 0; i < pacc.count; ++i) m.indices.push_back(base + i);
            }
        }
    if (m.indices.empty()) return make_error("mesh '" + file.string() + "' has no triangle primitives");
    if (need_normals) compute_normals(m);
    return m;
}

} // namespace

Result<Mesh> load_mesh(const fs::path& file) {
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) return make_error("mesh file '" + file.string() + "' not found");
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    Result<Mesh> m = ext == ".obj" ? load_obj(file) : (ext == ".gltf" || ext == ".glb") ? load_gltf(file)
                                                     : Result<Mesh>(make_error("mesh file '" + file.string() + "': use .obj, .gltf or .glb"));
    if (!m) return m;
    compute_tangents(*m);
    compute_bounds(*m);
    return m;
}

} // namespace pl::scene
