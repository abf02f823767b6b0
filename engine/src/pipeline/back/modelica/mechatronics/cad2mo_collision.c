/* cad2mo collision contact forces.
 *
 * The convex collision shapes of a model's bodies (each part the convex hull of its vertices, in
 * the body's frame_a coordinates, grown by a radius), the distance between two parts by GJK, their
 * penetration by EPA, and a contact law (Flores et al. 2011, a Hunt-Crossley type normal force
 * K*delta^n*(1 + 8(1-e)/(5e)*ddelta/ddelta0) with damping from the coefficient of restitution e,
 * and regularised Coulomb friction). Used by <Pkg>.Components.Collision.World through Modelica's
 * external "C" interface: the world is an ExternalObject built once, at initialisation, from the
 * shape file cad2mo writes beside it (<Pkg>/Resources/Collision/contact.txt, found by the tool
 * through its modelica:// URI; see cad2mo_collision_load), or from flat arrays.
 *
 * Conventions: a part point p (frame_a coordinates) of a body is at r_0 + transpose(R_T)*p in
 * world; R_T is MultiBody's frame_a.R.T (world to frame_a), r_0 its origin. Angular velocities
 * w_a are resolved in frame_a. Forces and torques are on each body, about its frame_a origin,
 * resolved in world. Matrices are passed row major (Modelica's C layout).
 *
 * Plain C99, no global state, every function static (a tool may include this file in several
 * translation units), nothing to link but the C library's libm.
 *
 * Written by cad2mo; MIT licence. */
#ifndef CAD2MO_COLLISION_C
#define CAD2MO_COLLISION_C

#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include <stdio.h>
#include "ModelicaUtilities.h"

/* Most vertices and faces the EPA polytope may grow to. */
#define C2MC_EPA_VERTS 256
#define C2MC_EPA_FACES 1024
#define C2MC_EPA_EDGES 1024

/* The entry points: a tool includes this file for each external function, so some are unused
 * in a translation unit. */
#if defined(__GNUC__) || defined(__clang__)
#define C2MC_API static __attribute__((unused))
#else
#define C2MC_API static
#endif

/* ---- small vector helpers ---- */

static double c2mc_dot(const double* a, const double* b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }

static void c2mc_sub(const double* a, const double* b, double* o) {
    o[0] = a[0] - b[0];
    o[1] = a[1] - b[1];
    o[2] = a[2] - b[2];
}

static void c2mc_cross(const double* a, const double* b, double* o) {
    double x = a[1] * b[2] - a[2] * b[1];
    double y = a[2] * b[0] - a[0] * b[2];
    double z = a[0] * b[1] - a[1] * b[0];
    o[0] = x;
    o[1] = y;
    o[2] = z;
}

static void c2mc_copy(const double* a, double* o) {
    o[0] = a[0];
    o[1] = a[1];
    o[2] = a[2];
}

/* ---- support mapping of a convex point set (world coordinates) ---- */

static int c2mc_support(const double* pts, int n, const double* d) {
    int i, best = 0;
    double bd = c2mc_dot(pts, d);
    for (i = 1; i < n; i++) {
        double x = c2mc_dot(pts + 3 * i, d);
        if (x > bd) {
            bd = x;
            best = i;
        }
    }
    return best;
}

/* A simplex vertex of the Minkowski difference A - B: w = a - b. */
typedef struct {
    double w[3], a[3], b[3];
    int ia, ib;
} c2mc_vert;

typedef struct {
    c2mc_vert v[4];
    double l[4]; /* barycentric weights of the closest point */
    int n;
} c2mc_simplex;

static void c2mc_cso(const double* A, int na, const double* B, int nb, const double* d, c2mc_vert* out) {
    double nd[3];
    nd[0] = -d[0];
    nd[1] = -d[1];
    nd[2] = -d[2];
    out->ia = c2mc_support(A, na, d);
    out->ib = c2mc_support(B, nb, nd);
    c2mc_copy(A + 3 * out->ia, out->a);
    c2mc_copy(B + 3 * out->ib, out->b);
    c2mc_sub(out->a, out->b, out->w);
}

/* ---- closest point of a simplex to the origin (Ericson's Voronoi region tests) ---- */

/* Segment a b: weights of a and b. */
static void c2mc_closest_segment(const double* a, const double* b, double* la, double* lb) {
    double ab[3], t, den;
    c2mc_sub(b, a, ab);
    t = -c2mc_dot(a, ab);
    den = c2mc_dot(ab, ab);
    if (t <= 0.0 || den <= 0.0) {
        *la = 1.0;
        *lb = 0.0;
    } else if (t >= den) {
        *la = 0.0;
        *lb = 1.0;
    } else {
        *lb = t / den;
        *la = 1.0 - *lb;
    }
}

/* Triangle a b c: weights (l[0], l[1], l[2]). */
static void c2mc_closest_triangle(const double* a, const double* b, const double* c, double* l) {
    double ab[3], ac[3], bp[3], cp[3], ap[3];
    double d1, d2, d3, d4, d5, d6, va, vb, vc, den, v, w;
    c2mc_sub(b, a, ab);
    c2mc_sub(c, a, ac);
    ap[0] = -a[0];
    ap[1] = -a[1];
    ap[2] = -a[2];
    d1 = c2mc_dot(ab, ap);
    d2 = c2mc_dot(ac, ap);
    if (d1 <= 0.0 && d2 <= 0.0) {
        l[0] = 1.0; l[1] = 0.0; l[2] = 0.0;
        return;
    }
    bp[0] = -b[0];
    bp[1] = -b[1];
    bp[2] = -b[2];
    d3 = c2mc_dot(ab, bp);
    d4 = c2mc_dot(ac, bp);
    if (d3 >= 0.0 && d4 <= d3) {
        l[0] = 0.0; l[1] = 1.0; l[2] = 0.0;
        return;
    }
    vc = d1 * d4 - d3 * d2;
    if (vc <= 0.0 && d1 >= 0.0 && d3 <= 0.0) {
        v = d1 / (d1 - d3);
        l[0] = 1.0 - v; l[1] = v; l[2] = 0.0;
        return;
    }
    cp[0] = -c[0];
    cp[1] = -c[1];
    cp[2] = -c[2];
    d5 = c2mc_dot(ab, cp);
    d6 = c2mc_dot(ac, cp);
    if (d6 >= 0.0 && d5 <= d6) {
        l[0] = 0.0; l[1] = 0.0; l[2] = 1.0;
        return;
    }
    vb = d5 * d2 - d1 * d6;
    if (vb <= 0.0 && d2 >= 0.0 && d6 <= 0.0) {
        w = d2 / (d2 - d6);
        l[0] = 1.0 - w; l[1] = 0.0; l[2] = w;
        return;
    }
    va = d3 * d6 - d5 * d4;
    if (va <= 0.0 && (d4 - d3) >= 0.0 && (d5 - d6) >= 0.0) {
        w = (d4 - d3) / ((d4 - d3) + (d5 - d6));
        l[0] = 0.0; l[1] = 1.0 - w; l[2] = w;
        return;
    }
    den = va + vb + vc;
    if (!(den > 0.0)) { /* degenerate (flat) triangle: its best edge */
        double s0, s1, best = -1.0, q[3];
        int e;
        const double* P[3];
        P[0] = a; P[1] = b; P[2] = c;
        for (e = 0; e < 3; e++) {
            const double* p0 = P[e];
            const double* p1 = P[(e + 1) % 3];
            double dd;
            c2mc_closest_segment(p0, p1, &s0, &s1);
            q[0] = s0 * p0[0] + s1 * p1[0];
            q[1] = s0 * p0[1] + s1 * p1[1];
            q[2] = s0 * p0[2] + s1 * p1[2];
            dd = c2mc_dot(q, q);
            if (best < 0.0 || dd < best) {
                best = dd;
                l[0] = l[1] = l[2] = 0.0;
                l[e] = s0;
                l[(e + 1) % 3] = s1;
            }
        }
        return;
    }
    v = vb / den;
    w = vc / den;
    l[0] = 1.0 - v - w; l[1] = v; l[2] = w;
}

/* Is the origin on the other side of plane (a,b,c) than d? Also when d is (within rounding) in
 * the plane: a flat tetrahedron encloses nothing, its closest point is on a face. */
static int c2mc_outside_plane(const double* a, const double* b, const double* c, const double* d) {
    double ab[3], ac[3], n[3], ad[3];
    double sp, sd;
    c2mc_sub(b, a, ab);
    c2mc_sub(c, a, ac);
    c2mc_cross(ab, ac, n);
    c2mc_sub(d, a, ad);
    sp = -c2mc_dot(a, n);
    sd = c2mc_dot(ad, n);
    if (fabs(sd) <= 1e-12 * sqrt(c2mc_dot(n, n) * c2mc_dot(ad, ad))) {
        return 1;
    }
    return sp * sd < 0.0;
}

/* Reduces the simplex to the vertices with positive weight; sets v to the closest point.
 * Returns 1 when the origin is inside the tetrahedron (simplex stays at 4). */
static int c2mc_simplex_solve(c2mc_simplex* s, double* v) {
    int i, k;
    double l[4] = {0.0, 0.0, 0.0, 0.0};
    if (s->n == 1) {
        l[0] = 1.0;
    } else if (s->n == 2) {
        c2mc_closest_segment(s->v[0].w, s->v[1].w, &l[0], &l[1]);
    } else if (s->n == 3) {
        c2mc_closest_triangle(s->v[0].w, s->v[1].w, s->v[2].w, l);
    } else {
        static const int F[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
        double best = -1.0;
        int inside = 1, f;
        for (f = 0; f < 4; f++) {
            const double* a = s->v[F[f][0]].w;
            const double* b = s->v[F[f][1]].w;
            const double* c = s->v[F[f][2]].w;
            if (c2mc_outside_plane(a, b, c, s->v[F[f][3]].w)) {
                double t[3], q[3], dd;
                inside = 0;
                c2mc_closest_triangle(a, b, c, t);
                for (k = 0; k < 3; k++) {
                    q[k] = t[0] * a[k] + t[1] * b[k] + t[2] * c[k];
                }
                dd = c2mc_dot(q, q);
                if (best < 0.0 || dd < best) {
                    best = dd;
                    l[0] = l[1] = l[2] = l[3] = 0.0;
                    l[F[f][0]] = t[0];
                    l[F[f][1]] = t[1];
                    l[F[f][2]] = t[2];
                }
            }
        }
        if (inside) {
            v[0] = v[1] = v[2] = 0.0;
            return 1;
        }
    }
    k = 0;
    v[0] = v[1] = v[2] = 0.0;
    for (i = 0; i < s->n; i++) {
        if (l[i] > 0.0) {
            s->v[k] = s->v[i];
            s->l[k] = l[i];
            v[0] += l[i] * s->v[i].w[0];
            v[1] += l[i] * s->v[i].w[1];
            v[2] += l[i] * s->v[i].w[2];
            k++;
        }
    }
    s->n = k;
    return 0;
}

/* GJK on the point sets A and B (world). Returns 0 when separated (v = closest point of A - B to
 * the origin, s the supporting simplex with weights), 1 when they intersect (s holds up to 4
 * vertices enclosing or touching the origin). */
static int c2mc_gjk(const double* A, int na, const double* B, int nb, c2mc_simplex* s, double* v) {
    int it, i, maxit = 64 + 4 * (na + nb);
    double vv, scale;
    c2mc_sub(A, B, v);
    s->n = 0;
    scale = c2mc_dot(v, v);
    vv = 1e300;
    for (it = 0; it < maxit; it++) {
        c2mc_vert w;
        double d[3], vw, nv;
        int dup = 0;
        d[0] = -v[0];
        d[1] = -v[1];
        d[2] = -v[2];
        c2mc_cso(A, na, B, nb, d, &w);
        if (c2mc_dot(w.w, w.w) > scale) {
            scale = c2mc_dot(w.w, w.w);
        }
        if (s->n > 0) {
            vv = c2mc_dot(v, v);
            vw = c2mc_dot(v, w.w);
            for (i = 0; i < s->n; i++) {
                if (s->v[i].ia == w.ia && s->v[i].ib == w.ib) {
                    dup = 1;
                }
            }
            /* No support point beyond the current one: v is the closest point (on polytopes the
             * support repeats a simplex vertex once the closest feature is found). */
            if (dup || vv - vw <= 1e-15 * vv) {
                return 0;
            }
        }
        s->v[s->n++] = w;
        if (c2mc_simplex_solve(s, v)) {
            return 1;
        }
        nv = c2mc_dot(v, v);
        if (nv <= 1e-30 * scale) {
            return 1;
        }
        if (s->n > 0 && it > 0 && nv >= vv) {
            return 0; /* no progress: rounding */
        }
    }
    return 0;
}

/* ---- EPA ---- */

typedef struct {
    int i[3];
    double n[3], d;
    int alive;
} c2mc_face;

typedef struct {
    c2mc_vert v[C2MC_EPA_VERTS];
    c2mc_face f[C2MC_EPA_FACES];
    int e[C2MC_EPA_EDGES][2];
    int nv, nf;
} c2mc_epa;

static int c2mc_epa_face(c2mc_epa* p, int a, int b, int c) {
    double ab[3], ac[3], n[3], len;
    c2mc_face* f;
    if (p->nf >= C2MC_EPA_FACES) {
        return 0;
    }
    c2mc_sub(p->v[b].w, p->v[a].w, ab);
    c2mc_sub(p->v[c].w, p->v[a].w, ac);
    c2mc_cross(ab, ac, n);
    len = sqrt(c2mc_dot(n, n));
    if (!(len > 0.0)) {
        return 1; /* degenerate: leave it out */
    }
    f = &p->f[p->nf++];
    f->i[0] = a;
    f->i[1] = b;
    f->i[2] = c;
    f->n[0] = n[0] / len;
    f->n[1] = n[1] / len;
    f->n[2] = n[2] / len;
    /* the distance from the face's vertices' mean: the least rounding */
    f->d = (c2mc_dot(f->n, p->v[a].w) + c2mc_dot(f->n, p->v[b].w) + c2mc_dot(f->n, p->v[c].w)) / 3.0;
    f->alive = 1;
    return 1;
}

/* Adds a direction's support point to the simplex when it raises its dimension. */
static int c2mc_blow_up(const double* A, int na, const double* B, int nb, c2mc_simplex* s, double scale) {
    static const double dirs[6][3] = {{1, 0, 0}, {-1, 0, 0}, {0, 1, 0}, {0, -1, 0}, {0, 0, 1}, {0, 0, -1}};
    double tol = 1e-10 * sqrt(scale);
    while (s->n < 4) {
        int k, added = 0;
        double cand[8][3];
        int nc = 0;
        if (s->n == 3) {
            double ab[3], ac[3], n[3];
            c2mc_sub(s->v[1].w, s->v[0].w, ab);
            c2mc_sub(s->v[2].w, s->v[0].w, ac);
            c2mc_cross(ab, ac, n);
            c2mc_copy(n, cand[nc++]);
            cand[nc][0] = -n[0]; cand[nc][1] = -n[1]; cand[nc][2] = -n[2];
            nc++;
        }
        for (k = 0; k < 6; k++) {
            c2mc_copy(dirs[k], cand[nc++]);
        }
        for (k = 0; k < nc && !added; k++) {
            c2mc_vert w;
            double dist = 0.0;
            c2mc_cso(A, na, B, nb, cand[k], &w);
            if (s->n == 0) {
                dist = 1.0;
            } else if (s->n == 1) {
                double d[3];
                c2mc_sub(w.w, s->v[0].w, d);
                dist = sqrt(c2mc_dot(d, d));
            } else if (s->n == 2) {
                double ab[3], aw[3], c[3], len;
                c2mc_sub(s->v[1].w, s->v[0].w, ab);
                c2mc_sub(w.w, s->v[0].w, aw);
                c2mc_cross(ab, aw, c);
                len = sqrt(c2mc_dot(ab, ab));
                dist = len > 0.0 ? sqrt(c2mc_dot(c, c)) / len : 0.0;
            } else {
                double ab[3], ac[3], n[3], aw[3], len;
                c2mc_sub(s->v[1].w, s->v[0].w, ab);
                c2mc_sub(s->v[2].w, s->v[0].w, ac);
                c2mc_cross(ab, ac, n);
                c2mc_sub(w.w, s->v[0].w, aw);
                len = sqrt(c2mc_dot(n, n));
                dist = len > 0.0 ? fabs(c2mc_dot(n, aw)) / len : 0.0;
            }
            if (dist > tol) {
                s->v[s->n++] = w;
                added = 1;
            }
        }
        if (!added) {
            return 0;
        }
    }
    return 1;
}

/* Penetration of A and B (they intersect; s from GJK). Returns 1 with depth >= 0, the normal n
 * (unit, from A towards B: moving B by depth*n separates them) and witness points; 0 when no
 * polytope could be built (touching, flat): depth 0. */
static int c2mc_epa_run(c2mc_epa* p, const double* A, int na, const double* B, int nb, c2mc_simplex* s,
                        double* depth, double* n, double* pa, double* pb) {
    static const int F[4][4] = {{0, 1, 2, 3}, {0, 3, 1, 2}, {0, 2, 3, 1}, {1, 3, 2, 0}};
    int i, k, it;
    double scale = 0.0, tol;
    if (s->n < 4) {
        double sc = 0.0;
        for (i = 0; i < s->n; i++) {
            double q = c2mc_dot(s->v[i].w, s->v[i].w);
            sc = q > sc ? q : sc;
        }
        if (!c2mc_blow_up(A, na, B, nb, s, sc > 0.0 ? sc : 1.0)) {
            return 0;
        }
    }
    p->nv = 4;
    p->nf = 0;
    for (i = 0; i < 4; i++) {
        double q;
        p->v[i] = s->v[i];
        q = c2mc_dot(p->v[i].w, p->v[i].w);
        scale = q > scale ? q : scale;
    }
    scale = sqrt(scale);
    tol = 1e-14 * (scale > 0.0 ? scale : 1.0);
    for (i = 0; i < 4; i++) {
        double o[3];
        int a = F[i][0], b = F[i][1], c = F[i][2];
        c2mc_epa_face(p, a, b, c);
        if (p->nf > 0 && p->f[p->nf - 1].i[0] == a && p->f[p->nf - 1].i[1] == b && p->f[p->nf - 1].i[2] == c) {
            c2mc_face* f = &p->f[p->nf - 1];
            c2mc_sub(p->v[F[i][3]].w, p->v[a].w, o);
            if (c2mc_dot(f->n, o) > 0.0) { /* inward: flip */
                f->i[1] = c;
                f->i[2] = b;
                f->n[0] = -f->n[0];
                f->n[1] = -f->n[1];
                f->n[2] = -f->n[2];
                f->d = -f->d;
            }
        }
    }
    if (p->nf < 4) {
        return 0;
    }
    for (i = 0; i < p->nf; i++) { /* the origin must be inside the tetrahedron */
        if (p->f[i].d < -tol) {
            return 0;
        }
    }
    for (it = 0; it < 4 * C2MC_EPA_VERTS; it++) {
        int best = -1, ne = 0, nvtx;
        double bd = 0.0, gap;
        c2mc_vert w;
        c2mc_face* f;
        for (i = 0; i < p->nf; i++) {
            if (p->f[i].alive && (best < 0 || p->f[i].d < bd)) {
                best = i;
                bd = p->f[i].d;
            }
        }
        if (best < 0) {
            return 0;
        }
        f = &p->f[best];
        c2mc_cso(A, na, B, nb, f->n, &w);
        gap = c2mc_dot(f->n, w.w) - f->d;
        nvtx = p->nv;
        for (i = 0; i < p->nv; i++) {
            if (p->v[i].ia == w.ia && p->v[i].ib == w.ib) {
                nvtx = -1;
            }
        }
        if (gap <= tol || nvtx < 0 || p->nv >= C2MC_EPA_VERTS) {
            /* converged: the face is in a face of A - B (within rounding). That face may be a
             * polygon split into several coplanar triangles: the witness points come from the
             * one holding the origin's projection q (the least residual). */
            double q[3], l[3], bestres = -1.0;
            int j, chosen = best;
            q[0] = f->d * f->n[0];
            q[1] = f->d * f->n[1];
            q[2] = f->d * f->n[2];
            l[0] = 1.0;
            l[1] = l[2] = 0.0;
            for (j = 0; j < p->nf; j++) {
                c2mc_face* g = &p->f[j];
                double a2[3], b2[3], c2[3], t[3], res[3], rr;
                double cr[3];
                c2mc_cross(g->n, f->n, cr);
                if (!g->alive || fabs(g->d - f->d) > 16.0 * tol || c2mc_dot(g->n, f->n) < 0.0 || c2mc_dot(cr, cr) > 1e-20) {
                    continue;
                }
                c2mc_sub(p->v[g->i[0]].w, q, a2);
                c2mc_sub(p->v[g->i[1]].w, q, b2);
                c2mc_sub(p->v[g->i[2]].w, q, c2);
                c2mc_closest_triangle(a2, b2, c2, t);
                for (k = 0; k < 3; k++) {
                    res[k] = t[0] * a2[k] + t[1] * b2[k] + t[2] * c2[k];
                }
                rr = c2mc_dot(res, res);
                if (bestres < 0.0 || rr < bestres) {
                    bestres = rr;
                    chosen = j;
                    c2mc_copy(t, l);
                }
            }
            *depth = f->d > 0.0 ? f->d : 0.0;
            c2mc_copy(f->n, n);
            f = &p->f[chosen];
            for (k = 0; k < 3; k++) {
                pa[k] = l[0] * p->v[f->i[0]].a[k] + l[1] * p->v[f->i[1]].a[k] + l[2] * p->v[f->i[2]].a[k];
                pb[k] = l[0] * p->v[f->i[0]].b[k] + l[1] * p->v[f->i[1]].b[k] + l[2] * p->v[f->i[2]].b[k];
            }
            return 1;
        }
        p->v[p->nv] = w;
        /* remove the faces that see w; their unshared edges are the horizon */
        for (i = 0; i < p->nf; i++) {
            double o[3];
            c2mc_face* g = &p->f[i];
            if (!g->alive) {
                continue;
            }
            c2mc_sub(w.w, p->v[g->i[0]].w, o);
            if (c2mc_dot(g->n, o) > tol * 1e-2) {
                g->alive = 0;
                for (k = 0; k < 3; k++) {
                    int a = g->i[k], b = g->i[(k + 1) % 3], j, found = -1;
                    for (j = 0; j < ne; j++) {
                        if (p->e[j][0] == b && p->e[j][1] == a) {
                            found = j;
                            break;
                        }
                    }
                    if (found >= 0) {
                        p->e[found][0] = p->e[ne - 1][0];
                        p->e[found][1] = p->e[ne - 1][1];
                        ne--;
                    } else if (ne < C2MC_EPA_EDGES) {
                        p->e[ne][0] = a;
                        p->e[ne][1] = b;
                        ne++;
                    }
                }
            }
        }
        if (ne == 0) {
            return 0;
        }
        /* compact dead faces */
        k = 0;
        for (i = 0; i < p->nf; i++) {
            if (p->f[i].alive) {
                p->f[k++] = p->f[i];
            }
        }
        p->nf = k;
        for (i = 0; i < ne; i++) {
            if (!c2mc_epa_face(p, p->e[i][0], p->e[i][1], p->nv)) {
                break;
            }
        }
        p->nv++;
    }
    return 0;
}

/* ---- one pair of parts ---- */

typedef struct {
    double dist;   /* > 0: distance; < 0: minus the penetration depth */
    double pa[3];  /* witness point on A (world) */
    double pb[3];  /* witness point on B */
    double n[3];   /* unit normal from A towards B */
    int ok;        /* 0: the normal is undefined (concentric cores) */
} c2mc_result;

/* A and B: world vertices of the cores; ra, rb: radii. */
static void c2mc_pair(c2mc_epa* scratch, const double* A, int na, double ra, const double* B, int nb, double rb,
                      c2mc_result* r) {
    c2mc_simplex s;
    double v[3];
    int k;
    r->ok = 1;
    if (!c2mc_gjk(A, na, B, nb, &s, v)) {
        double d = sqrt(c2mc_dot(v, v));
        double pa[3] = {0.0, 0.0, 0.0}, pb[3] = {0.0, 0.0, 0.0};
        int i;
        for (i = 0; i < s.n; i++) {
            for (k = 0; k < 3; k++) {
                pa[k] += s.l[i] * s.v[i].a[k];
                pb[k] += s.l[i] * s.v[i].b[k];
            }
        }
        if (d > 0.0) {
            for (k = 0; k < 3; k++) {
                r->n[k] = -v[k] / d;
            }
        } else {
            r->n[0] = 0.0; r->n[1] = 0.0; r->n[2] = 1.0;
            r->ok = 0;
        }
        r->dist = d - ra - rb;
        for (k = 0; k < 3; k++) {
            r->pa[k] = pa[k] + ra * r->n[k];
            r->pb[k] = pb[k] - rb * r->n[k];
        }
        return;
    }
    {
        double depth = 0.0, n[3] = {0.0, 0.0, 1.0}, pa[3], pb[3];
        if (!c2mc_epa_run(scratch, A, na, B, nb, &s, &depth, n, pa, pb)) {
            /* touching cores (no volume to expand): depth 0 */
            depth = 0.0;
            r->ok = 0;
            c2mc_copy(s.v[0].a, pa);
            c2mc_copy(s.v[0].b, pb);
        }
        r->dist = -depth - ra - rb;
        c2mc_copy(n, r->n);
        for (k = 0; k < 3; k++) {
            r->pa[k] = pa[k] + ra * n[k];
            r->pb[k] = pb[k] - rb * n[k];
        }
    }
}

/* Part vertices (frame_a coordinates, n x 3) to world at r_0, R_T. */
static void c2mc_to_world(const double* p, int n, const double* r0, const double* RT, double* out) {
    int i, k;
    for (i = 0; i < n; i++) {
        for (k = 0; k < 3; k++) {
            /* transpose(R_T)*p: column k of R_T */
            out[3 * i + k] = r0[k] + RT[0 * 3 + k] * p[3 * i + 0] + RT[1 * 3 + k] * p[3 * i + 1] + RT[2 * 3 + k] * p[3 * i + 2];
        }
    }
}

/* ---- the contact law's damping from the coefficient of restitution ---- */

/* The normal force K*delta^n*(1 + chi*ddelta/v0) (v0: approach speed at contact onset, the force
 * never pulling) makes an impact of any mass, stiffness and speed rebound with the same ratio:
 * scaled, x'' = -x^n*(1 + chi*x')^+ from x = 0, x' = 1, and e = -x' when x returns to 0. */
static double c2mc_rebound(double chi, double ne) {
    double x = 0.0, v = 1.0, h = 1e-3;
    int it;
    for (it = 0; it < 1000000; it++) {
        double k1x, k1v, k2x, k2v, k3x, k3v, k4x, k4v, xn, vn, f;
#define C2MC_ACC(X, V) (f = -pow((X) > 0.0 ? (X) : 0.0, ne) * (1.0 + chi * (V)), f < 0.0 ? f : 0.0)
        k1x = v;
        k1v = C2MC_ACC(x, v);
        k2x = v + 0.5 * h * k1v;
        k2v = C2MC_ACC(x + 0.5 * h * k1x, k2x);
        k3x = v + 0.5 * h * k2v;
        k3v = C2MC_ACC(x + 0.5 * h * k2x, k3x);
        k4x = v + h * k3v;
        k4v = C2MC_ACC(x + h * k3x, k4x);
#undef C2MC_ACC
        xn = x + h / 6.0 * (k1x + 2.0 * k2x + 2.0 * k3x + k4x);
        vn = v + h / 6.0 * (k1v + 2.0 * k2v + 2.0 * k3v + k4v);
        if (xn <= 0.0 && it > 0) {
            /* back at x = 0 within this step: the speed there, linearly */
            double s = x / (x - xn);
            return -(v + s * (vn - v));
        }
        if (vn <= 0.0 && 1.0 + chi * vn <= 0.0) {
            return -vn; /* the force has vanished: the body leaves at this speed */
        }
        x = xn;
        v = vn;
    }
    return 0.0;
}

/* The damping factor chi giving restitution e (0 < e <= 1) at exponent ne, by bisection. */
static double c2mc_chi(double e, double ne) {
    double lo = 0.0, hi = 1.0;
    int i;
    if (e >= 1.0) {
        return 0.0;
    }
    while (c2mc_rebound(hi, ne) > e && hi < 1e12) {
        hi *= 4.0;
    }
    for (i = 0; i < 60; i++) {
        double mid = 0.5 * (lo + hi);
        if (c2mc_rebound(mid, ne) > e) {
            lo = mid;
        } else {
            hi = mid;
        }
    }
    return 0.5 * (lo + hi);
}

/* ---- the world ---- */

typedef struct {
    int nBodies, nParts, nVertices;
    int* partBody;     /* [nParts] (0-based) */
    int* partStart;    /* [nParts + 1] first vertex of each part */
    double* radius;    /* [nParts] */
    double* vertices;  /* [nVertices * 3] frame_a coordinates */
    double* scratch;   /* [nVertices * 3] world coordinates at the last evaluation */
    double* impact;    /* [nParts * nParts] approach speed at contact onset, 0 = not in contact */
    double* stiffness; /* [nBodies] */
    double* restitution;
    double* friction;
    double* chi;       /* [nBodies] damping factor from the body's restitution */
    double* sphere;    /* [nParts * 4] bounding sphere of each part: centre (frame_a), radius */
    double exponent, vReg, vImpactMin;
    int touching;      /* touching part pairs at the last evaluation */
    c2mc_epa* epa;
    unsigned char* checked; /* [nBodies * nBodies] 1: the pair's contacts are computed (set by load) */
} c2mc_world;

C2MC_API void cad2mo_collision_close(void* object) {
    c2mc_world* w = (c2mc_world*)object;
    if (w == NULL) {
        return;
    }
    free(w->partBody);
    free(w->partStart);
    free(w->radius);
    free(w->vertices);
    free(w->scratch);
    free(w->impact);
    free(w->stiffness);
    free(w->restitution);
    free(w->friction);
    free(w->chi);
    free(w->sphere);
    free(w->epa);
    free(w->checked);
    free(w);
}

/* The world of nBodies bodies and nParts convex parts: part i belongs to body partBody[i]
 * (1-based, as Modelica counts), has partVertices[i] vertices (the next ones of `vertices`,
 * nVertices x 3, frame_a coordinates, m) and radius partRadius[i] (m). Contact law per body:
 * stiffness (N/m^exponent), restitution (0 < e <= 1), friction coefficient; a pair uses the series
 * stiffness, the smaller restitution and the geometric mean of the friction coefficients.
 * vReg: the slip speed below which friction is proportional to it (m/s); vImpactMin: the least
 * approach speed the damping is scaled by (m/s). Returns NULL only through ModelicaError. */
C2MC_API void* cad2mo_collision_open(int nBodies, int nParts, const int* partBody, const int* partVertices,
                                   const double* partRadius, int nVertices, const double* vertices,
                                   const double* stiffness, const double* restitution, const double* friction,
                                   double exponent, double vReg, double vImpactMin) {
    c2mc_world* w;
    int i, total = 0;
    if (nBodies < 1 || nParts < 0 || nVertices < 0) {
        ModelicaError("cad2mo collision: bad sizes");
        return NULL;
    }
    for (i = 0; i < nParts; i++) {
        if (partBody[i] < 1 || partBody[i] > nBodies) {
            ModelicaError("cad2mo collision: a part's body index is out of range");
            return NULL;
        }
        if (partVertices[i] < 1) {
            ModelicaError("cad2mo collision: a part without vertices");
            return NULL;
        }
        if (!(partRadius[i] >= 0.0)) {
            ModelicaError("cad2mo collision: a negative part radius");
            return NULL;
        }
        total += partVertices[i];
    }
    if (total != nVertices) {
        ModelicaError("cad2mo collision: the parts' vertex counts do not add up to the vertices given");
        return NULL;
    }
    for (i = 0; i < nBodies; i++) {
        if (!(stiffness[i] > 0.0) || !(restitution[i] > 0.0) || restitution[i] > 1.0 || !(friction[i] >= 0.0)) {
            ModelicaError("cad2mo collision: contact law parameters out of range (stiffness > 0, 0 < restitution <= 1, friction >= 0)");
            return NULL;
        }
    }
    if (!(exponent > 0.0) || !(vReg > 0.0) || !(vImpactMin > 0.0)) {
        ModelicaError("cad2mo collision: exponent, vReg and vImpactMin must be positive");
        return NULL;
    }
    w = (c2mc_world*)calloc(1, sizeof(c2mc_world));
    if (w == NULL) {
        ModelicaError("cad2mo collision: out of memory");
        return NULL;
    }
    w->nBodies = nBodies;
    w->nParts = nParts;
    w->nVertices = nVertices;
    w->partBody = (int*)malloc(sizeof(int) * (size_t)(nParts > 0 ? nParts : 1));
    w->partStart = (int*)malloc(sizeof(int) * (size_t)(nParts + 1));
    w->radius = (double*)malloc(sizeof(double) * (size_t)(nParts > 0 ? nParts : 1));
    w->vertices = (double*)malloc(sizeof(double) * 3 * (size_t)(nVertices > 0 ? nVertices : 1));
    w->scratch = (double*)malloc(sizeof(double) * 3 * (size_t)(nVertices > 0 ? nVertices : 1));
    w->impact = (double*)calloc(nParts > 0 ? (size_t)nParts * (size_t)nParts : 1, sizeof(double));
    w->stiffness = (double*)malloc(sizeof(double) * (size_t)nBodies);
    w->restitution = (double*)malloc(sizeof(double) * (size_t)nBodies);
    w->friction = (double*)malloc(sizeof(double) * (size_t)nBodies);
    w->chi = (double*)malloc(sizeof(double) * (size_t)nBodies);
    w->sphere = (double*)malloc(sizeof(double) * 4 * (size_t)(nParts > 0 ? nParts : 1));
    w->epa = (c2mc_epa*)malloc(sizeof(c2mc_epa));
    if (!w->partBody || !w->partStart || !w->radius || !w->vertices || !w->scratch || !w->impact || !w->stiffness ||
        !w->restitution || !w->friction || !w->chi || !w->sphere || !w->epa) {
        cad2mo_collision_close(w);
        ModelicaError("cad2mo collision: out of memory");
        return NULL;
    }
    total = 0;
    for (i = 0; i < nParts; i++) {
        w->partBody[i] = partBody[i] - 1;
        w->partStart[i] = total;
        w->radius[i] = partRadius[i];
        total += partVertices[i];
    }
    w->partStart[nParts] = total;
    if (nVertices > 0) {
        memcpy(w->vertices, vertices, sizeof(double) * 3 * (size_t)nVertices);
    }
    for (i = 0; i < nParts; i++) { /* bounding spheres: the broad phase */
        int j, k, nv = w->partStart[i + 1] - w->partStart[i];
        const double* v = w->vertices + 3 * w->partStart[i];
        double* sp = w->sphere + 4 * i;
        double r2 = 0.0;
        for (k = 0; k < 3; k++) {
            sp[k] = 0.0;
            for (j = 0; j < nv; j++) {
                sp[k] += v[3 * j + k] / nv;
            }
        }
        for (j = 0; j < nv; j++) {
            double d[3], q;
            c2mc_sub(v + 3 * j, sp, d);
            q = c2mc_dot(d, d);
            r2 = q > r2 ? q : r2;
        }
        sp[3] = sqrt(r2) * (1.0 + 1e-12) + w->radius[i];
    }
    memcpy(w->stiffness, stiffness, sizeof(double) * (size_t)nBodies);
    memcpy(w->restitution, restitution, sizeof(double) * (size_t)nBodies);
    memcpy(w->friction, friction, sizeof(double) * (size_t)nBodies);
    for (i = 0; i < nBodies; i++) {
        w->chi[i] = c2mc_chi(restitution[i], exponent);
    }
    w->exponent = exponent;
    w->vReg = vReg;
    w->vImpactMin = vImpactMin;
    return w;
}

/* Velocity (world) of the world point p of body i. */
static void c2mc_point_velocity(const double* r_0, const double* R_T, const double* v_0, const double* w_a, int i,
                                const double* p, double* out) {
    double wo[3], rp[3], c[3];
    int k;
    const double* RT = R_T + 9 * i;
    const double* wa = w_a + 3 * i;
    for (k = 0; k < 3; k++) { /* angular velocity in world: transpose(R_T)*w_a */
        wo[k] = RT[0 * 3 + k] * wa[0] + RT[1 * 3 + k] * wa[1] + RT[2 * 3 + k] * wa[2];
    }
    c2mc_sub(p, r_0 + 3 * i, rp);
    c2mc_cross(wo, rp, c);
    for (k = 0; k < 3; k++) {
        out[k] = v_0[3 * i + k] + c[k];
    }
}

static void c2mc_apply(double* force, double* torque, const double* r_0, int i, const double* p, const double* f, double sign) {
    double rp[3], t[3];
    int k;
    c2mc_sub(p, r_0 + 3 * i, rp);
    c2mc_cross(rp, f, t);
    for (k = 0; k < 3; k++) {
        force[3 * i + k] += sign * f[k];
        torque[3 * i + k] += sign * t[k];
    }
}

/* Contact forces: for n bodies at r_0[n,3], R_T[n,3,3], v_0[n,3], w_a[n,3] (resolved in frame_a),
 * every pair (i, j) with checked[i,j] or checked[j,i] nonzero (checked NULL: the pairs the world
 * was loaded with); force[n,3] and torque[n,3] on each body about its frame_a origin, resolved in
 * world. */
C2MC_API void cad2mo_collision_eval(void* object, const double* r_0, const double* R_T, const double* v_0, const double* w_a,
                                 const int* checked, int n, double* force, double* torque) {
    c2mc_world* w = (c2mc_world*)object;
    int p, q, i, k, touching = 0;
    if (w == NULL) {
        return;
    }
    if (n != w->nBodies) {
        ModelicaError("cad2mo collision: the number of bodies differs from the world's");
        return;
    }
    for (i = 0; i < 3 * n; i++) {
        force[i] = 0.0;
        torque[i] = 0.0;
    }
    for (p = 0; p < w->nParts; p++) {
        int b = w->partBody[p];
        c2mc_to_world(w->vertices + 3 * w->partStart[p], w->partStart[p + 1] - w->partStart[p], r_0 + 3 * b, R_T + 9 * b,
                      w->scratch + 3 * w->partStart[p]);
    }
    for (p = 0; p < w->nParts; p++) {
        for (q = p + 1; q < w->nParts; q++) {
            int a = w->partBody[p], b = w->partBody[q];
            c2mc_result r;
            double delta, rate, va[3], vb[3], dv[3], c[3], vt[3], vtn, Fn, K, mu, ne, fvec[3], damping;
            double* imp = &w->impact[(size_t)p * (size_t)w->nParts + (size_t)q];
            if (a == b) {
                continue;
            }
            if (checked != NULL ? !(checked[a * n + b] || checked[b * n + a]) : (w->checked == NULL || !w->checked[a * n + b])) {
                continue;
            }
            {
                double ca[3], cb[3], d[3];
                c2mc_to_world(w->sphere + 4 * p, 1, r_0 + 3 * a, R_T + 9 * a, ca);
                c2mc_to_world(w->sphere + 4 * q, 1, r_0 + 3 * b, R_T + 9 * b, cb);
                c2mc_sub(cb, ca, d);
                if (sqrt(c2mc_dot(d, d)) > w->sphere[4 * p + 3] + w->sphere[4 * q + 3]) {
                    *imp = 0.0; /* bounding spheres apart */
                    continue;
                }
            }
            c2mc_pair(w->epa, w->scratch + 3 * w->partStart[p], w->partStart[p + 1] - w->partStart[p], w->radius[p],
                      w->scratch + 3 * w->partStart[q], w->partStart[q + 1] - w->partStart[q], w->radius[q], &r);
            if (!(r.dist < 0.0)) {
                *imp = 0.0;
                continue;
            }
            touching++;
            delta = -r.dist;
            for (k = 0; k < 3; k++) {
                c[k] = 0.5 * (r.pa[k] + r.pb[k]);
            }
            c2mc_point_velocity(r_0, R_T, v_0, w_a, a, c, va);
            c2mc_point_velocity(r_0, R_T, v_0, w_a, b, c, vb);
            c2mc_sub(vb, va, dv); /* velocity of B relative to A at the contact point */
            rate = -c2mc_dot(dv, r.n); /* d(delta)/dt */
            if (*imp == 0.0) {
                *imp = rate > w->vImpactMin ? rate : w->vImpactMin; /* contact onset */
            }
            ne = w->exponent;
            K = pow(pow(w->stiffness[a], -1.0 / ne) + pow(w->stiffness[b], -1.0 / ne), -ne);
            /* the smaller restitution: the larger damping */
            damping = w->chi[a] > w->chi[b] ? w->chi[a] : w->chi[b];
            mu = sqrt(w->friction[a] * w->friction[b]);
            Fn = K * pow(delta, ne) * (1.0 + damping * rate / *imp);
            if (Fn < 0.0) {
                Fn = 0.0;
            }
            vtn = c2mc_dot(dv, r.n);
            for (k = 0; k < 3; k++) {
                vt[k] = dv[k] - vtn * r.n[k];
            }
            vtn = sqrt(c2mc_dot(vt, vt) + w->vReg * w->vReg);
            for (k = 0; k < 3; k++) { /* on B: pushed along n, friction against its slip */
                fvec[k] = Fn * r.n[k] - mu * Fn * vt[k] / vtn;
            }
            c2mc_apply(force, torque, r_0, b, c, fvec, 1.0);
            c2mc_apply(force, torque, r_0, a, c, fvec, -1.0);
        }
    }
    w->touching = touching;
}

/* ---- the shape file (Resources/Collision/contact.txt) ---- */

/* Largest shape file read, and most bodies, parts and vertices it may declare: bounds on what a
 * damaged or hostile file can make the simulation allocate. */
#define C2MC_MAX_FILE_BYTES (1024L * 1024L * 1024L)
#define C2MC_MAX_BODIES 100000
#define C2MC_MAX_PARTS 1000000
#define C2MC_MAX_VERTICES 20000000

typedef struct {
    const char* file; /* for messages */
    char* text;
    char* at;
    int line;
} c2mc_reader;

/* Skips blanks, line ends (counted) and comments (# to the end of the line). */
static void c2mc_skip(c2mc_reader* r) {
    for (;;) {
        char c = *r->at;
        if (c == '\n') {
            r->line++;
            r->at++;
        } else if (c == ' ' || c == '\t' || c == '\r') {
            r->at++;
        } else if (c == '#') {
            while (*r->at != '\0' && *r->at != '\n') {
                r->at++;
            }
        } else {
            return;
        }
    }
}

/* The next word (up to a blank), copied into buf (cap bytes); 0 at the end of the file. */
static int c2mc_word(c2mc_reader* r, char* buf, size_t cap) {
    size_t n = 0;
    c2mc_skip(r);
    while (*r->at != '\0' && *r->at != ' ' && *r->at != '\t' && *r->at != '\r' && *r->at != '\n') {
        if (n + 1 < cap) {
            buf[n++] = *r->at;
        }
        r->at++;
    }
    buf[n] = '\0';
    return n > 0;
}

static int c2mc_int(c2mc_reader* r, long lo, long hi, long* out) {
    char* end;
    long v;
    c2mc_skip(r);
    v = strtol(r->at, &end, 10);
    if (end == r->at || v < lo || v > hi) {
        return 0;
    }
    r->at = end;
    *out = v;
    return 1;
}

static int c2mc_real(c2mc_reader* r, double* out) {
    char* end;
    double v;
    c2mc_skip(r);
    v = strtod(r->at, &end);
    if (end == r->at || !(v == v) || v > 1e300 || v < -1e300) {
        return 0;
    }
    r->at = end;
    *out = v;
    return 1;
}

/* The whole file as a NUL-terminated string (NULL with a message in err). */
static char* c2mc_read_file(const char* fileName, char* err, size_t cap) {
    FILE* f = fopen(fileName, "rb");
    char* text;
    long size;
    if (f == NULL) {
        snprintf(err, cap, "cannot open the collision shape file \"%s\"", fileName);
        return NULL;
    }
    if (fseek(f, 0, SEEK_END) != 0 || (size = ftell(f)) < 0 || fseek(f, 0, SEEK_SET) != 0) {
        fclose(f);
        snprintf(err, cap, "cannot read the collision shape file \"%s\"", fileName);
        return NULL;
    }
    if (size > C2MC_MAX_FILE_BYTES) {
        fclose(f);
        snprintf(err, cap, "the collision shape file \"%s\" is larger than %ld bytes", fileName, C2MC_MAX_FILE_BYTES);
        return NULL;
    }
    text = (char*)malloc((size_t)size + 1);
    if (text == NULL) {
        fclose(f);
        snprintf(err, cap, "out of memory reading the collision shape file \"%s\"", fileName);
        return NULL;
    }
    if (size > 0 && fread(text, 1, (size_t)size, f) != (size_t)size) {
        fclose(f);
        free(text);
        snprintf(err, cap, "cannot read the collision shape file \"%s\"", fileName);
        return NULL;
    }
    fclose(f);
    text[size] = '\0';
    if (strlen(text) != (size_t)size) {
        free(text);
        snprintf(err, cap, "the collision shape file \"%s\" is not text (it holds a NUL byte)", fileName);
        return NULL;
    }
    return text;
}

/* Reads the shape file written by cad2mo:
 *
 *   cad2mo-collision 1
 *   bodies <n>
 *   body <k> <name>                    n lines, k = 1..n in turn
 *   part <k> <radius> <nVertices>      then nVertices lines "x y z" (frame_a of body k, m)
 *   allow <a> <b>                      a pair of bodies allowed to touch (not computed)
 *   end
 *
 * and builds the world. The file's bodies must be bodyNames, in that order (a shape file of
 * another model or of an older version of this one is refused, naming the first difference).
 * mayTouch[nMay, 2] (1-based body indices) are further pairs allowed to touch. An empty fileName
 * gives a world without parts (no contact forces). Errors name the file and line. */
C2MC_API void* cad2mo_collision_load(const char* fileName, int nBodies, const char** bodyNames, int nMay, const int* mayTouch,
                                   const double* stiffness, const double* restitution, const double* friction,
                                   double exponent, double vReg, double vImpactMin) {
    c2mc_reader r;
    char word[1024], err[1400];
    long version, n, k, nv, a, b;
    long nParts = 0, nVertices = 0, capParts = 64, capVertices = 1024;
    int *partBody = NULL, *partVertices = NULL, i, ok = 0;
    double *partRadius = NULL, *vertices = NULL;
    unsigned char* checked = NULL;
    c2mc_world* w = NULL;
    err[0] = '\0';
    if (nBodies < 1 || nBodies > C2MC_MAX_BODIES || nMay < 0) {
        ModelicaError("cad2mo collision: bad sizes");
        return NULL;
    }
    checked = (unsigned char*)malloc((size_t)nBodies * (size_t)nBodies);
    if (checked == NULL) {
        ModelicaError("cad2mo collision: out of memory");
        return NULL;
    }
    for (a = 0; a < nBodies; a++) {
        for (b = 0; b < nBodies; b++) {
            checked[a * nBodies + b] = (unsigned char)(a != b);
        }
    }
    if (fileName == NULL || fileName[0] == '\0') {
        w = (c2mc_world*)cad2mo_collision_open(nBodies, 0, NULL, NULL, NULL, 0, NULL, stiffness, restitution, friction, exponent, vReg, vImpactMin);
        if (w != NULL) {
            w->checked = checked;
        } else {
            free(checked);
        }
        return w;
    }
    r.file = fileName;
    r.line = 1;
    r.text = c2mc_read_file(fileName, err, sizeof err);
    if (r.text == NULL) {
        free(checked);
        ModelicaError(err);
        return NULL;
    }
    r.at = r.text;
    partBody = (int*)malloc(sizeof(int) * (size_t)capParts);
    partVertices = (int*)malloc(sizeof(int) * (size_t)capParts);
    partRadius = (double*)malloc(sizeof(double) * (size_t)capParts);
    vertices = (double*)malloc(sizeof(double) * 3 * (size_t)capVertices);
    if (!partBody || !partVertices || !partRadius || !vertices) {
        snprintf(err, sizeof err, "out of memory");
        goto done;
    }
    if (!c2mc_word(&r, word, sizeof word) || strcmp(word, "cad2mo-collision") != 0 || !c2mc_int(&r, 1, 1, &version)) {
        snprintf(err, sizeof err, "line %d: not a cad2mo collision shape file of version 1", r.line);
        goto done;
    }
    if (!c2mc_word(&r, word, sizeof word) || strcmp(word, "bodies") != 0 || !c2mc_int(&r, 1, C2MC_MAX_BODIES, &n)) {
        snprintf(err, sizeof err, "line %d: expected \"bodies <count>\"", r.line);
        goto done;
    }
    if (n != nBodies) {
        snprintf(err, sizeof err, "line %d: the file has %ld bodies, the model %d (a shape file of another model or version?)", r.line, n, nBodies);
        goto done;
    }
    for (i = 0; i < nBodies; i++) {
        if (!c2mc_word(&r, word, sizeof word) || strcmp(word, "body") != 0 || !c2mc_int(&r, i + 1, i + 1, &k) || !c2mc_word(&r, word, sizeof word)) {
            snprintf(err, sizeof err, "line %d: expected \"body %d <name>\"", r.line, i + 1);
            goto done;
        }
        if (bodyNames != NULL && strcmp(word, bodyNames[i]) != 0) {
            snprintf(err, sizeof err, "line %d: body %d is %s in the file but %s in the model (a shape file of another model or version?)", r.line, i + 1, word,
                     bodyNames[i]);
            goto done;
        }
    }
    for (;;) {
        if (!c2mc_word(&r, word, sizeof word)) {
            snprintf(err, sizeof err, "line %d: the file ends without \"end\" (truncated?)", r.line);
            goto done;
        }
        if (strcmp(word, "end") == 0) {
            break;
        }
        if (strcmp(word, "part") == 0) {
            double radius;
            if (!c2mc_int(&r, 1, nBodies, &k) || !c2mc_real(&r, &radius) || !(radius >= 0.0) || !c2mc_int(&r, 1, C2MC_MAX_VERTICES, &nv)) {
                snprintf(err, sizeof err, "line %d: expected \"part <body 1..%d> <radius >= 0> <vertices >= 1>\"", r.line, nBodies);
                goto done;
            }
            if (nParts >= C2MC_MAX_PARTS || nVertices + nv > C2MC_MAX_VERTICES) {
                snprintf(err, sizeof err, "line %d: more than %d parts or %d vertices", r.line, C2MC_MAX_PARTS, C2MC_MAX_VERTICES);
                goto done;
            }
            if (nParts == capParts) {
                int *pb, *pv;
                double* pr;
                capParts *= 2;
                pb = (int*)realloc(partBody, sizeof(int) * (size_t)capParts);
                partBody = pb != NULL ? pb : partBody;
                pv = (int*)realloc(partVertices, sizeof(int) * (size_t)capParts);
                partVertices = pv != NULL ? pv : partVertices;
                pr = (double*)realloc(partRadius, sizeof(double) * (size_t)capParts);
                partRadius = pr != NULL ? pr : partRadius;
                if (pb == NULL || pv == NULL || pr == NULL) {
                    snprintf(err, sizeof err, "out of memory");
                    goto done;
                }
            }
            while (nVertices + nv > capVertices) {
                double* pv;
                capVertices *= 2;
                pv = (double*)realloc(vertices, sizeof(double) * 3 * (size_t)capVertices);
                if (pv == NULL) {
                    snprintf(err, sizeof err, "out of memory");
                    goto done;
                }
                vertices = pv;
            }
            partBody[nParts] = (int)k;
            partVertices[nParts] = (int)nv;
            partRadius[nParts] = radius;
            for (k = 0; k < 3 * nv; k++) {
                if (!c2mc_real(&r, &vertices[3 * nVertices + k])) {
                    snprintf(err, sizeof err, "line %d: expected %ld finite vertex coordinates of part %ld", r.line, 3 * nv, nParts + 1);
                    goto done;
                }
            }
            nParts++;
            nVertices += nv;
        } else if (strcmp(word, "allow") == 0) {
            if (!c2mc_int(&r, 1, nBodies, &a) || !c2mc_int(&r, 1, nBodies, &b)) {
                snprintf(err, sizeof err, "line %d: expected \"allow <body> <body>\" (1..%d)", r.line, nBodies);
                goto done;
            }
            checked[(a - 1) * nBodies + (b - 1)] = 0;
            checked[(b - 1) * nBodies + (a - 1)] = 0;
        } else {
            snprintf(err, sizeof err, "line %d: unknown entry \"%s\" (part, allow or end)", r.line, word);
            goto done;
        }
    }
    for (i = 0; i < nMay; i++) {
        a = mayTouch[2 * i];
        b = mayTouch[2 * i + 1];
        if (a < 1 || a > nBodies || b < 1 || b > nBodies) {
            snprintf(err, sizeof err, "mayTouch[%d] names a body outside 1..%d", i + 1, nBodies);
            goto done;
        }
        checked[(a - 1) * nBodies + (b - 1)] = 0;
        checked[(b - 1) * nBodies + (a - 1)] = 0;
    }
    ok = 1;
done:
    free(r.text);
    if (ok) {
        w = (c2mc_world*)cad2mo_collision_open(nBodies, (int)nParts, partBody, partVertices, partRadius, (int)nVertices, vertices, stiffness, restitution,
                                               friction, exponent, vReg, vImpactMin);
    }
    free(partBody);
    free(partVertices);
    free(partRadius);
    free(vertices);
    if (!ok) {
        char msg[2800];
        free(checked);
        snprintf(msg, sizeof msg, "cad2mo collision: %s: %s", fileName, err);
        ModelicaError(msg);
        return NULL;
    }
    if (w != NULL) {
        w->checked = checked;
    } else {
        free(checked);
    }
    return w;
}

/* Contact forces with the pairs the world was loaded with ([`cad2mo_collision_load`]). */
C2MC_API void cad2mo_collision_forces(void* object, const double* r_0, const double* R_T, const double* v_0, const double* w_a, int n, double* force,
                                    double* torque) {
    cad2mo_collision_eval(object, r_0, R_T, v_0, w_a, NULL, n, force, torque);
}

/* The number of touching part pairs at the last evaluation. */
C2MC_API int cad2mo_collision_contacts(void* object) {
    return object == NULL ? 0 : ((c2mc_world*)object)->touching;
}

/* Distance query between two parts (vertices in their bodies' frame_a coordinates) at poses
 * (r0, R_T). Writes dist (> 0 distance, < 0 minus the penetration depth), the witness points
 * pa, pb (world) and the unit normal n from A towards B. Returns 1, or 0 when the normal is
 * undefined (concentric or exactly touching cores) or no memory. */
C2MC_API int cad2mo_collision_query(const double* va, int na, double ra, const double* r0a, const double* RTa,
                                  const double* vb, int nb, double rb, const double* r0b, const double* RTb,
                                  double* dist, double* pa, double* pb, double* n) {
    double* A = (double*)malloc(sizeof(double) * 3 * (size_t)(na + nb));
    c2mc_epa* e = (c2mc_epa*)malloc(sizeof(c2mc_epa));
    c2mc_result r;
    int ok, k;
    *dist = 0.0;
    for (k = 0; k < 3; k++) {
        pa[k] = pb[k] = n[k] = 0.0;
    }
    if (A == NULL || e == NULL || na < 1 || nb < 1) {
        free(A);
        free(e);
        return 0;
    }
    c2mc_to_world(va, na, r0a, RTa, A);
    c2mc_to_world(vb, nb, r0b, RTb, A + 3 * na);
    c2mc_pair(e, A, na, ra, A + 3 * na, nb, rb, &r);
    *dist = r.dist;
    c2mc_copy(r.pa, pa);
    c2mc_copy(r.pb, pb);
    c2mc_copy(r.n, n);
    ok = r.ok;
    free(A);
    free(e);
    return ok;
}

#endif
