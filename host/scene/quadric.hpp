// Garland-Heckbert quadric error metric (000_c9f7e5de708ecbb3.txt L6004-6033): the squared
// distance of a point v = [x y z 1] to a set of planes p = [A B C D] is
//   Delta(v) = sum_p (p^T v)^2 = v^T (sum_p p p^T) v = v^T Q v,
// and the quadric of a collapsed pair is Q1 + Q2. Q is symmetric, so 10 coefficients; each
// plane may carry a weight (face area, or a border penalty), and `weight` sums them so the cost
// can be turned back into a distance (RMS over the planes).
#pragma once

#include <array>
#include <cmath>

namespace pl::scene {

struct Quadric {
    // Upper triangle of the 4x4 matrix, row by row: a2 ab ac ad, b2 bc bd, c2 cd, d2.
    double a2 = 0, ab = 0, ac = 0, ad = 0, b2 = 0, bc = 0, bd = 0, c2 = 0, cd = 0, d2 = 0;
    double weight = 0;

    // w * p p^T for the plane n.x + d = 0 (n unit length): Delta = w * distance^2.
    static Quadric plane(const std::array<double, 3>& n, double d, double w) {
        Quadric q;
        q.a2 = w * n[0] * n[0], q.ab = w * n[0] * n[1], q.ac = w * n[0] * n[2], q.ad = w * n[0] * d;
        q.b2 = w * n[1] * n[1], q.bc = w * n[1] * n[2], q.bd = w * n[1] * d;
        q.c2 = w * n[2] * n[2], q.cd = w * n[2] * d;
        q.d2 = w * d * d;
        q.weight = w;
        return q;
    }

    Quadric& operator+=(const Quadric& o) {
        a2 += o.a2, ab += o.ab, ac += o.ac, ad += o.ad, b2 += o.b2, bc += o.bc, bd += o.bd;
        c2 += o.c2, cd += o.cd, d2 += o.d2, weight += o.weight;
        return *this;
    }
    friend Quadric operator+(Quadric a, const Quadric& b) { return a += b; }

    // v^T Q v with v = [x y z 1]. Mathematically >= 0 (a sum of squares); rounding can leave a
    // value a few ulps below zero, which callers clamp only where they need a distance.
    double evaluate(const std::array<double, 3>& v) const {
        const double x = v[0], y = v[1], z = v[2];
        return a2 * x * x + 2 * ab * x * y + 2 * ac * x * z + 2 * ad * x + b2 * y * y + 2 * bc * y * z + 2 * bd * y +
               c2 * z * z + 2 * cd * z + d2;
    }

    // The minimiser of v^T Q v: grad = 0 gives the 3x3 system A v = -b (A the upper-left block,
    // b the last column). Returns false when A is (nearly) singular - a flat or straight
    // neighbourhood, whose minimisers form a plane or a line - judged by det(A) against the scale
    // (trace/3)^3 so the test does not depend on the mesh's units: 1e-9 is an eigenvalue ratio
    // far below that of any curved neighbourhood a generator produces (a 48-segment sphere's
    // vertex is ~3e-4), so curved vertices get the optimum and flat ones the fallback.
    bool optimum(std::array<double, 3>& out) const {
        const double det = a2 * (b2 * c2 - bc * bc) - ab * (ab * c2 - bc * ac) + ac * (ab * bc - b2 * ac);
        const double scale = (a2 + b2 + c2) / 3.0;
        if (!(scale > 0) || !(det > 1e-9 * scale * scale * scale)) return false;
        // Cramer's rule on A v = r with r = -(ad, bd, cd).
        const double r0 = -ad, r1 = -bd, r2 = -cd;
        out[0] = (r0 * (b2 * c2 - bc * bc) - ab * (r1 * c2 - bc * r2) + ac * (r1 * bc - b2 * r2)) / det;
        out[1] = (a2 * (r1 * c2 - r2 * bc) - r0 * (ab * c2 - bc * ac) + ac * (ab * r2 - r1 * ac)) / det;
        out[2] = (a2 * (b2 * r2 - bc * r1) - ab * (ab * r2 - r1 * ac) + r0 * (ab * bc - b2 * ac)) / det;
        return std::isfinite(out[0]) && std::isfinite(out[1]) && std::isfinite(out[2]);
    }
};

} // namespace pl::scene
