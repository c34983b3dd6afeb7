// The Utah teapot (Martin Newell, 1975): bicubic Bézier patches, here in the compact form of
// the classic SGI/freeglut data — 10 patches over 127 control points, mirrored across the
// xz and yz planes (rim, body, lid and bottom four times, handle and spout twice) to give the
// 32 patches of the original. Coordinates are z-up in the data and converted to our y-up world.
#include "scene/mesh.hpp"

#include <glm/glm.hpp>

#include <cmath>

namespace pl::scene {

namespace {

// clang-format off
const int kPatches[10][16] = {
    {102, 103, 104, 105, 4, 5, 6, 7, 8, 9, 10, 11, 12, 13, 14, 15},           // rim
    {12, 13, 14, 15, 16, 17, 18, 19, 20, 21, 22, 23, 24, 25, 26, 27},         // body
    {24, 25, 26, 27, 29, 30, 31, 32, 33, 34, 35, 36, 37, 38, 39, 40},         // body
    {96, 96, 96, 96, 97, 98, 99, 100, 101, 101, 101, 101, 0, 1, 2, 3},        // lid
    {0, 1, 2, 3, 106, 107, 108, 109, 110, 111, 112, 113, 114, 115, 116, 117}, // lid
    {118, 118, 118, 118, 124, 122, 119, 121, 123, 126, 125, 120, 40, 39, 38, 37}, // bottom
    {41, 42, 43, 44, 45, 46, 47, 48, 49, 50, 51, 52, 53, 54, 55, 56},         // handle
    {53, 54, 55, 56, 57, 58, 59, 60, 61, 62, 63, 64, 28, 65, 66, 67},         // handle
    {68, 69, 70, 71, 72, 73, 74, 75, 76, 77, 78, 79, 80, 81, 82, 83},         // spout
    {80, 81, 82, 83, 84, 85, 86, 87, 88, 89, 90, 91, 92, 93, 94, 95},         // spout
};

const float kPoints[127][3] = {
    {0.2f, 0, 2.7f}, {0.2f, -0.112f, 2.7f}, {0.112f, -0.2f, 2.7f}, {0, -0.2f, 2.7f},
    {1.3375f, 0, 2.53125f}, {1.3375f, -0.749f, 2.53125f}, {0.749f, -1.3375f, 2.53125f}, {0, -1.3375f, 2.53125f},
    {1.4375f, 0, 2.53125f}, {1.4375f, -0.805f, 2.53125f}, {0.805f, -1.4375f, 2.53125f}, {0, -1.4375f, 2.53125f},
    {1.5f, 0, 2.4f}, {1.5f, -0.84f, 2.4f}, {0.84f, -1.5f, 2.4f}, {0, -1.5f, 2.4f},
    {1.75f, 0, 1.875f}, {1.75f, -0.98f, 1.875f}, {0.98f, -1.75f, 1.875f}, {0, -1.75f, 1.875f},
    {2, 0, 1.35f}, {2, -1.12f, 1.35f}, {1.12f, -2, 1.35f}, {0, -2, 1.35f},
    {2, 0, 0.9f}, {2, -1.12f, 0.9f}, {1.12f, -2, 0.9f}, {0, -2, 0.9f},
    {-2, 0, 0.9f},
    {2, 0, 0.45f}, {2, -1.12f, 0.45f}, {1.12f, -2, 0.45f}, {0, -2, 0.45f},
    {1.5f, 0, 0.225f}, {1.5f, -0.84f, 0.225f}, {0.84f, -1.5f, 0.225f}, {0, -1.5f, 0.225f},
    {1.5f, 0, 0.15f}, {1.5f, -0.84f, 0.15f}, {0.84f, -1.5f, 0.15f}, {0, -1.5f, 0.15f},
    {-1.6f, 0, 2.025f}, {-1.6f, -0.3f, 2.025f}, {-1.5f, -0.3f, 2.25f}, {-1.5f, 0, 2.25f},
    {-2.3f, 0, 2.025f}, {-2.3f, -0.3f, 2.025f}, {-2.5f, -0.3f, 2.25f}, {-2.5f, 0, 2.25f},
    {-2.7f, 0, 2.025f}, {-2.7f, -0.3f, 2.025f}, {-3, -0.3f, 2.25f}, {-3, 0, 2.25f},
    {-2.7f, 0, 1.8f}, {-2.7f, -0.3f, 1.8f}, {-3, -0.3f, 1.8f}, {-3, 0, 1.8f},
    {-2.7f, 0, 1.575f}, {-2.7f, -0.3f, 1.575f}, {-3, -0.3f, 1.35f}, {-3, 0, 1.35f},
    {-2.5f, 0, 1.125f}, {-2.5f, -0.3f, 1.125f}, {-2.65f, -0.3f, 0.9375f}, {-2.65f, 0, 0.9375f},
    {-2, -0.3f, 0.9f}, {-1.9f, -0.3f, 0.6f}, {-1.9f, 0, 0.6f},
    {1.7f, 0, 1.425f}, {1.7f, -0.66f, 1.425f}, {1.7f, -0.66f, 0.6f}, {1.7f, 0, 0.6f},
    {2.6f, 0, 1.425f}, {2.6f, -0.66f, 1.425f}, {3.1f, -0.66f, 0.825f}, {3.1f, 0, 0.825f},
    {2.3f, 0, 2.1f}, {2.3f, -0.25f, 2.1f}, {2.4f, -0.25f, 2.025f}, {2.4f, 0, 2.025f},
    {2.7f, 0, 2.4f}, {2.7f, -0.25f, 2.4f}, {3.3f, -0.25f, 2.4f}, {3.3f, 0, 2.4f},
    {2.8f, 0, 2.475f}, {2.8f, -0.25f, 2.475f}, {3.525f, -0.25f, 2.49375f}, {3.525f, 0, 2.49375f},
    {2.9f, 0, 2.475f}, {2.9f, -0.15f, 2.475f}, {3.45f, -0.15f, 2.5125f}, {3.45f, 0, 2.5125f},
    {2.8f, 0, 2.4f}, {2.8f, -0.15f, 2.4f}, {3.2f, -0.15f, 2.4f}, {3.2f, 0, 2.4f},
    {0, 0, 3.15f}, {0.8f, 0, 3.15f}, {0.8f, -0.45f, 3.15f}, {0.45f, -0.8f, 3.15f},
    {0, -0.8f, 3.15f}, {0, 0, 2.85f},
    {1.4f, 0, 2.4f}, {1.4f, -0.784f, 2.4f}, {0.784f, -1.4f, 2.4f}, {0, -1.4f, 2.4f},
    {0.4f, 0, 2.55f}, {0.4f, -0.224f, 2.55f}, {0.224f, -0.4f, 2.55f}, {0, -0.4f, 2.55f},
    {1.3f, 0, 2.55f}, {1.3f, -0.728f, 2.55f}, {0.728f, -1.3f, 2.55f}, {0, -1.3f, 2.55f},
    {1.3f, 0, 2.4f}, {1.3f, -0.728f, 2.4f}, {0.728f, -1.3f, 2.4f}, {0, -1.3f, 2.4f},
    {0, 0, 0}, {1.425f, -0.798f, 0}, {1.5f, 0, 0.075f}, {1.425f, 0, 0},
    {0.798f, -1.425f, 0}, {0, -1.5f, 0.075f}, {0, -1.425f, 0}, {1.5f, -0.84f, 0.075f},
    {0.84f, -1.5f, 0.075f},
};
// clang-format on

glm::vec3 bezier(const glm::vec3 p[4], float t) {
    float s = 1.0f - t;
    return s * s * s * p[0] + 3.0f * s * s * t * p[1] + 3.0f * s * t * t * p[2] + t * t * t * p[3];
}

glm::vec3 bezier_d(const glm::vec3 p[4], float t) {
    float s = 1.0f - t;
    return 3.0f * s * s * (p[1] - p[0]) + 6.0f * s * t * (p[2] - p[1]) + 3.0f * t * t * (p[3] - p[2]);
}

struct Patch {
    glm::vec3 cp[4][4];
};

glm::vec3 eval(const Patch& P, float u, float v, glm::vec3* du, glm::vec3* dv) {
    glm::vec3 rows[4], cols[4];
    for (int j = 0; j < 4; ++j) rows[j] = bezier(P.cp[j], u);
    for (int k = 0; k < 4; ++k) {
        glm::vec3 c[4] = {P.cp[0][k], P.cp[1][k], P.cp[2][k], P.cp[3][k]};
        cols[k] = bezier(c, v);
    }
    glm::vec3 drow[4];
    for (int j = 0; j < 4; ++j) drow[j] = bezier_d(P.cp[j], u);
    *du = bezier(drow, v);
    *dv = bezier_d(rows, v);
    return bezier(rows, v);
}

} // namespace

Result<Mesh> teapot_mesh(int subdivisions) {
    if (subdivisions < 1 || subdivisions > 64)
        return make_error("mesh generator 'teapot': subdivisions must be 1..64");
    // Data space is z-up; rotate by -90 degrees about x (y <- z, z <- -y, a proper rotation that
    // keeps winding), centre the bounding box and scale the longest side (spout to handle,
    // 6.525 units) to 2.
    const float scale = 2.0f / 6.525f;
    const glm::vec3 centre(0.2625f, 1.575f, 0.0f);  // in y-up space
    auto convert = [&](const float* p, float sx, float sy) {
        glm::vec3 q(p[0] * sx, p[2], -p[1] * sy);
        return (q - centre) * scale;
    };
    std::vector<Patch> patches;
    for (int i = 0; i < 10; ++i) {
        // Mirrored copies reverse the u order so every copy keeps the original's orientation.
        int copies = i < 6 ? 4 : 2;
        const float signs[4][2] = {{1, 1}, {1, -1}, {-1, 1}, {-1, -1}};
        for (int c = 0; c < copies; ++c) {
            float sx = signs[c][0], sy = signs[c][1];
            bool reverse = (sx * sy) < 0;
            Patch P;
            for (int j = 0; j < 4; ++j)
                for (int k = 0; k < 4; ++k) {
                    int kk = reverse ? 3 - k : k;
                    P.cp[j][k] = convert(kPoints[kPatches[i][j * 4 + kk]], sx, sy);
                }
            patches.push_back(P);
        }
    }
    Mesh m;
    int n = subdivisions;
    for (size_t pi = 0; pi < patches.size(); ++pi) {
        uint32_t base = static_cast<uint32_t>(m.vertices.size());
        for (int b = 0; b <= n; ++b)
            for (int a = 0; a <= n; ++a) {
                float u = float(a) / n, v = float(b) / n;
                glm::vec3 du, dv;
                glm::vec3 p = eval(patches[pi], u, v, &du, &dv);
                glm::vec3 nrm = glm::cross(du, dv);
                if (glm::length(nrm) < 1e-6f) {
                    // Degenerate edge (the lid knob and the bottom centre collapse a whole row of
                    // control points): take the normal just inside the patch.
                    glm::vec3 du2, dv2;
                    eval(patches[pi], u, v < 0.5f ? 1e-3f : 1.0f - 1e-3f, &du2, &dv2);
                    nrm = glm::cross(du2, dv2);
                }
                Vertex vert{};
                for (int k = 0; k < 3; ++k) vert.position[k] = p[k];
                glm::vec3 nn = glm::length(nrm) > 0 ? glm::normalize(nrm) : glm::vec3(0, 1, 0);
                for (int k = 0; k < 3; ++k) vert.normal[k] = nn[k];
                vert.uv[0] = u;
                vert.uv[1] = v;
                m.vertices.push_back(vert);
            }
        for (int b = 0; b < n; ++b)
            for (int a = 0; a < n; ++a) {
                uint32_t i0 = base + b * (n + 1) + a, i1 = i0 + 1, i2 = i0 + (n + 1), i3 = i2 + 1;
                m.indices.insert(m.indices.end(), {i0, i1, i2, i1, i3, i2});
            }
    }
    // The data's patches are all oriented alike; make that orientation CCW-outward (positive
    // signed volume), flipping normals and winding together if needed.
    double volume = 0;
    for (size_t t = 0; t + 2 < m.indices.size(); t += 3) {
        glm::vec3 a(m.vertices[m.indices[t]].position[0], m.vertices[m.indices[t]].position[1], m.vertices[m.indices[t]].position[2]);
        glm::vec3 b(m.vertices[m.indices[t + 1]].position[0], m.vertices[m.indices[t + 1]].position[1], m.vertices[m.indices[t + 1]].position[2]);
        glm::vec3 c(m.vertices[m.indices[t + 2]].position[0], m.vertices[m.indices[t + 2]].position[1], m.vertices[m.indices[t + 2]].position[2]);
        volume += glm::dot(a, glm::cross(b, c));
    }
    // The geometric winding decides; vertex normals must agree with it.
    if (volume < 0)
        for (size_t t = 0; t + 2 < m.indices.size(); t += 3) std::swap(m.indices[t + 1], m.indices[t + 2]);
    // Per patch, make the du x dv normals agree with the (now outward) winding: patches whose
    // parametrisation runs the other way get their normals flipped as a whole.
    size_t per_patch_idx = static_cast<size_t>(n) * n * 6, per_patch_vtx = static_cast<size_t>(n + 1) * (n + 1);
    for (size_t pi = 0; pi < patches.size(); ++pi) {
        double agree = 0;
        for (size_t t = pi * per_patch_idx; t < (pi + 1) * per_patch_idx; t += 3) {
            auto P = [&](size_t k) {
                const Vertex& x = m.vertices[m.indices[t + k]];
                return glm::vec3(x.position[0], x.position[1], x.position[2]);
            };
            glm::vec3 g = glm::cross(P(1) - P(0), P(2) - P(0));
            for (size_t k = 0; k < 3; ++k) {
                const Vertex& x = m.vertices[m.indices[t + k]];
                agree += glm::dot(g, glm::vec3(x.normal[0], x.normal[1], x.normal[2]));
            }
        }
        if (agree < 0)
            for (size_t vi = pi * per_patch_vtx; vi < (pi + 1) * per_patch_vtx; ++vi)
                for (float& c : m.vertices[vi].normal) c = -c;
    }
    return m;
}

} // namespace pl::scene
