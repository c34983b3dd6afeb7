// Procedural meshes: positions, normals, UVs and tangents; CCW front faces seen from outside.
#include "scene/mesh.hpp"

#include <algorithm>
#include <cmath>

namespace pl::scene {

namespace {

constexpr float kPi = 3.14159265358979f;

double arg(const std::map<std::string, double>& a, const std::string& k, double def) {
    auto it = a.find(k);
    return it == a.end() ? def : it->second;
}

void push(Mesh& m, float px, float py, float pz, float nx, float ny, float nz, float u, float v) {
    m.vertices.push_back({{px, py, pz}, {nx, ny, nz}, {u, v}, {0, 0, 0, 1}});
}

Mesh plane(float size, int seg) {
    Mesh m;
    for (int j = 0; j <= seg; ++j)
        for (int i = 0; i <= seg; ++i) {
            float u = float(i) / seg, v = float(j) / seg;
            push(m, (u - 0.5f) * size, 0, (v - 0.5f) * size, 0, 1, 0, u, v);
        }
    for (int j = 0; j < seg; ++j)
        for (int i = 0; i < seg; ++i) {
            uint32_t a = j * (seg + 1) + i, b = a + 1, c = a + seg + 1, d = c + 1;
            // Seen from +Y: a(-,-) c(-,+) b(+,-): a -> c -> b is counter-clockwise.
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    return m;
}

Mesh cube(float size) {
    Mesh m;
    float h = size * 0.5f;
    // Each face: normal n, and axes (t, b) with t x b = n so (t,b) is CCW seen from outside.
    const float faces[6][9] = {{1, 0, 0, 0, 0, -1, 0, 1, 0},  {-1, 0, 0, 0, 0, 1, 0, 1, 0},
                               {0, 1, 0, 1, 0, 0, 0, 0, -1},  {0, -1, 0, 1, 0, 0, 0, 0, 1},
                               {0, 0, 1, 1, 0, 0, 0, 1, 0},   {0, 0, -1, -1, 0, 0, 0, 1, 0}};
    for (const auto& f : faces) {
        uint32_t base = static_cast<uint32_t>(m.vertices.size());
        for (int k = 0; k < 4; ++k) {
            float s = (k == 1 || k == 2) ? 1.0f : -1.0f, t = (k >= 2) ? 1.0f : -1.0f;
            push(m, h * (f[0] + s * f[3] + t * f[6]), h * (f[1] + s * f[4] + t * f[7]), h * (f[2] + s * f[5] + t * f[8]),
                 f[0], f[1], f[2], (s + 1) * 0.5f, 1.0f - (t + 1) * 0.5f);
        }
        m.indices.insert(m.indices.end(), {base, base + 1, base + 2, base, base + 2, base + 3});
    }
    return m;
}

Mesh sphere(float r, int seg, int rings) {
    Mesh m;
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= seg; ++i) {
            float u = float(i) / seg, v = float(j) / rings;
            float phi = u * 2 * kPi, theta = v * kPi;
            float x = std::sin(theta) * std::sin(phi), y = std::cos(theta), z = std::sin(theta) * std::cos(phi);
            push(m, r * x, r * y, r * z, x, y, z, u, v);
        }
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < seg; ++i) {
            uint32_t a = j * (seg + 1) + i, b = a + 1, c = a + seg + 1, d = c + 1;
            m.indices.insert(m.indices.end(), {a, c, b, b, c, d});
        }
    return m;
}

Mesh torus(float R, float r, int seg, int rings) {
    Mesh m;
    for (int j = 0; j <= rings; ++j)
        for (int i = 0; i <= seg; ++i) {
            float u = float(i) / seg, v = float(j) / rings;
            float phi = u * 2 * kPi, theta = v * 2 * kPi;
            float cx = std::sin(phi), cz = std::cos(phi);
            float nx = std::cos(theta) * cx, ny = std::sin(theta), nz = std::cos(theta) * cz;
            push(m, R * cx + r * nx, r * ny, R * cz + r * nz, nx, ny, nz, u, v);
        }
    for (int j = 0; j < rings; ++j)
        for (int i = 0; i < seg; ++i) {
            uint32_t a = j * (seg + 1) + i, b = a + 1, c = a + seg + 1, d = c + 1;
            m.indices.insert(m.indices.end(), {a, b, c, b, d, c});
        }
    return m;
}

Error bad_arg(const std::string& gen, const std::string& name, const std::string& range) {
    return make_error("mesh generator '" + gen + "': " + name + " must be " + range);
}

} // namespace

Result<Mesh> teapot_mesh(int subdivisions);  // teapot.cpp

std::vector<std::string> generator_names() { return {"plane", "cube", "sphere", "torus", "teapot"}; }

Result<Mesh> generate_mesh(const std::string& gen, const std::map<std::string, double>& a) {
    Mesh m;
    double size = arg(a, "size", gen == "plane" ? 2.0 : 1.0), radius = arg(a, "radius", gen == "torus" ? 0.7 : 0.5);
    double seg = arg(a, "segments", gen == "plane" ? 1 : 48), rings = arg(a, "rings", 24), tube = arg(a, "tube", 0.25);
    if (size <= 0 || size > 1e6) return bad_arg(gen, "size", "> 0");
    if (radius <= 0 || radius > 1e6) return bad_arg(gen, "radius", "> 0");
    if (tube <= 0 || tube > 1e6) return bad_arg(gen, "tube", "> 0");
    bool plane_seg = gen == "plane";
    if (seg < (plane_seg ? 1 : 3) || seg > 4096) return bad_arg(gen, "segments", plane_seg ? "1..4096" : "3..4096");
    if (rings < 2 || rings > 4096) return bad_arg(gen, "rings", "2..4096");
    if (gen == "plane") m = plane(float(size), int(seg));
    else if (gen == "cube") m = cube(float(size));
    else if (gen == "sphere") m = sphere(float(radius), int(seg), int(rings));
    else if (gen == "torus") m = torus(float(radius), float(tube), int(seg), int(rings));
    else if (gen == "teapot") {
        auto t = teapot_mesh(static_cast<int>(arg(a, "subdivisions", 8)));
        if (!t) return t.error();
        m = std::move(t.value());
        if (size != 1.0)
            for (auto& v : m.vertices)
                for (float& c : v.position) c *= float(size);
    }
    else {
        auto names = generator_names();
        Error e = make_error("unknown mesh generator '" + gen + "'");
        std::string near = nearest_name(gen, names);
        if (!near.empty()) e.hint = "did you mean '" + near + "'?";
        e.notes.push_back("generators: plane, cube, sphere, torus, teapot");
        return e;
    }
    compute_tangents(m);
    compute_bounds(m);
    return m;
}

void compute_tangents(Mesh& m) {
    std::vector<float> acc(m.vertices.size() * 6, 0.0f);  // tangent xyz, bitangent xyz
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        const Vertex* v[3] = {&m.vertices[m.indices[t]], &m.vertices[m.indices[t + 1]], &m.vertices[m.indices[t + 2]]};
        float e1[3], e2[3];
        for (int k = 0; k < 3; ++k) e1[k] = v[1]->position[k] - v[0]->position[k], e2[k] = v[2]->position[k] - v[0]->position[k];
        float du1 = v[1]->uv[0] - v[0]->uv[0], dv1 = v[1]->uv[1] - v[0]->uv[1];
        float du2 = v[2]->uv[0] - v[0]->uv[0], dv2 = v[2]->uv[1] - v[0]->uv[1];
        float det = du1 * dv2 - du2 * dv1;
        if (std::fabs(det) < 1e-12f) continue;
        float r = 1.0f / det;
        for (int c = 0; c < 3; ++c) {
            size_t i = m.indices[t + c];
            for (int k = 0; k < 3; ++k) {
                acc[i * 6 + k] += (e1[k] * dv2 - e2[k] * dv1) * r;
                acc[i * 6 + 3 + k] += (e2[k] * du1 - e1[k] * du2) * r;
            }
        }
    }
    for (size_t i = 0; i < m.vertices.size(); ++i) {
        Vertex& v = m.vertices[i];
        float* t = &acc[i * 6];
        float* b = &acc[i * 6 + 3];
        const float* n = v.normal;
        float d = t[0] * n[0] + t[1] * n[1] + t[2] * n[2];
        float g[3] = {t[0] - n[0] * d, t[1] - n[1] * d, t[2] - n[2] * d};  // Gram-Schmidt
        float len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        if (len < 1e-8f) {
            // No UV gradient: any unit vector orthogonal to n.
            float ax[3] = {std::fabs(n[0]) < 0.9f ? 1.0f : 0.0f, std::fabs(n[0]) < 0.9f ? 0.0f : 1.0f, 0.0f};
            float dd = ax[0] * n[0] + ax[1] * n[1];
            g[0] = ax[0] - n[0] * dd, g[1] = ax[1] - n[1] * dd, g[2] = -n[2] * dd;
            len = std::sqrt(g[0] * g[0] + g[1] * g[1] + g[2] * g[2]);
        }
        for (int k = 0; k < 3; ++k) v.tangent[k] = g[k] / len;
        float c[3] = {n[1] * g[2] - n[2] * g[1], n[2] * g[0] - n[0] * g[2], n[0] * g[1] - n[1] * g[0]};
        v.tangent[3] = (c[0] * b[0] + c[1] * b[1] + c[2] * b[2]) < 0.0f ? -1.0f : 1.0f;
    }
}

void compute_bounds(Mesh& m) {
    if (m.vertices.empty()) return;
    for (int k = 0; k < 3; ++k) m.bounds_min[k] = m.bounds_max[k] = m.vertices[0].position[k];
    for (const auto& v : m.vertices)
        for (int k = 0; k < 3; ++k) {
            m.bounds_min[k] = std::min(m.bounds_min[k], v.position[k]);
            m.bounds_max[k] = std::max(m.bounds_max[k], v.position[k]);
        }
}

} // namespace pl::scene
