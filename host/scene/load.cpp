// Mesh files: .obj through tinyobjloader, .gltf/.glb through tinygltf (Debian ships both as
// compiled libraries). Everything becomes one indexed triangle list in our Vertex layout.
#include "scene/mesh.hpp"
#include "util/files.hpp"

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

// A face's triangles as corner indices into its vertex list. Quads split along the shorter
// diagonal (as tinyobjloader does, so existing meshes are unchanged); larger polygons are
// fanned from their first corner, in linear time: tinyobjloader's own triangulation of an
// n-gon is quadratic and hung on a face of 200,000 corners.
void triangulate_face(const tinyobj::attrib_t& a, const tinyobj::index_t* f, size_t n, std::vector<size_t>& out) {
    out.clear();
    if (n < 3) return;
    if (n == 4) {
        auto sq = [&](const tinyobj::index_t& p, const tinyobj::index_t& q) {
            float d = 0;
            for (int k = 0; k < 3; ++k) {
                size_t i = 3 * size_t(p.vertex_index) + size_t(k), j = 3 * size_t(q.vertex_index) + size_t(k);
                if (p.vertex_index < 0 || q.vertex_index < 0 || i >= a.vertices.size() || j >= a.vertices.size()) return 0.0f;
                float e = a.vertices[j] - a.vertices[i];
                d += e * e;
            }
            return d;
        };
        if (sq(f[0], f[2]) < sq(f[1], f[3])) out = {0, 1, 2, 0, 2, 3};
        else out = {0, 1, 3, 1, 2, 3};
        return;
    }
    for (size_t k = 1; k + 1 < n; ++k) out.insert(out.end(), {0, k, k + 1});
}

Result<Mesh> load_obj(const fs::path& file) {
    tinyobj::ObjReaderConfig cfg;
    cfg.triangulate = false;  // see triangulate_face
    cfg.vertex_color = false;
    tinyobj::ObjReader reader;
    if (!reader.ParseFromFile(file.string(), cfg))
        return make_error("cannot load mesh '" + file.string() + "': " + reader.Error());
    const auto& attrib = reader.GetAttrib();
    Mesh m;
    bool has_normals = !attrib.normals.empty();
    std::map<std::tuple<int, int, int>, uint32_t> dedupe;
    // tinyobjloader counts a face's corners in an unsigned char: a face of 256 or more corners
    // wraps, and the counts no longer add up to the indices. Refuse it rather than misread it.
    for (const auto& shape : reader.GetShapes()) {
        size_t sum = 0;
        for (auto c : shape.mesh.num_face_vertices) sum += c;
        if (sum != shape.mesh.indices.size())
            return make_error("mesh '" + file.string() + "': a face has 256 or more corners, more than the OBJ reader can count; "
                              "triangulate the mesh in a modelling tool");
    }
    std::vector<size_t> corners;
    for (const auto& shape : reader.GetShapes())
        for (size_t face = 0, first = 0; face < shape.mesh.num_face_vertices.size(); first += shape.mesh.num_face_vertices[face++]) {
            size_t n = shape.mesh.num_face_vertices[face];
            if (first + n > shape.mesh.indices.size()) break;
            triangulate_face(attrib, &shape.mesh.indices[first], n, corners);
            for (size_t c : corners) {
                const tinyobj::index_t& idx = shape.mesh.indices[first + c];
                auto key = std::make_tuple(idx.vertex_index, idx.normal_index, idx.texcoord_index);
                auto it = dedupe.find(key);
                if (it != dedupe.end()) {
                    m.indices.push_back(it->second);
                    continue;
                }
                // Offsets in size_t: an index near INT_MAX (a face "f 5555555555") would overflow
                // 3 * index in int, which is undefined (found by tests/fuzz, fuzz_mesh).
                const size_t vi = size_t(idx.vertex_index), ni = size_t(idx.normal_index), ti = size_t(idx.texcoord_index);
                if (idx.vertex_index < 0 || 3 * vi + 2 >= attrib.vertices.size())
                    return make_error("mesh '" + file.string() + "': a face refers to a vertex that does not exist");
                Vertex v{};
                for (size_t k = 0; k < 3; ++k) v.position[k] = attrib.vertices[3 * vi + k];
                if (idx.normal_index >= 0 && 3 * ni + 2 < attrib.normals.size())
                    for (size_t k = 0; k < 3; ++k) v.normal[k] = attrib.normals[3 * ni + k];
                if (idx.texcoord_index >= 0 && 2 * ti + 1 < attrib.texcoords.size()) {
                    v.uv[0] = attrib.texcoords[2 * ti];
                    v.uv[1] = 1.0f - attrib.texcoords[2 * ti + 1];  // OBJ v is bottom-up
                }
                uint32_t slot = static_cast<uint32_t>(m.vertices.size());
                m.vertices.push_back(v);
                dedupe.emplace(key, slot);
                m.indices.push_back(slot);
            }
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
    if (auto ok = check_regular_file(file, max_asset_bytes, "mesh"); !ok) return ok.error();
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
