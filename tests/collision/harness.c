/* Test harness of cad2mo_collision.c (tests/collision_c.rs runs it).
 *
 *   harness query   reads one pair per line on stdin:
 *                   na ra va[na*3] r0a[3] RTa[9] nb rb vb[nb*3] r0b[3] RTb[9]
 *                   and writes per line: ok dist pa[3] pb[3] n[3] (17 significant digits)
 *   harness eval    reads lines as query, then v_0a[3] w_aa[3] v_0b[3] w_ab[3] stiffness friction
 *                   vReg, and evaluates the two bodies' contact forces (restitution 1, exponent 1.5)
 *                   through a world: writes the query's answer, then force[2,3] and torque[2,3]
 *   harness drop e stiffness exponent mass radius height dt
 *                   drops a sphere (one vertex grown by radius) on a fixed box under gravity
 *                   through the world's contact law, integrated with semi-implicit Euler at
 *                   the fixed step dt, and writes one line per bounce: v_in v_out apex
 *   harness load FILE NAME...
 *                   builds the world from a package's shape file (Resources/Collision/contact.txt)
 *                   for the bodies NAME... (as Mechatronics lists them), reads each body's
 *                   r_0[3] R_T[9] from stdin (velocities zero) and writes one line
 *                   "parts vertices checkedPairs touching", then per body force[3] torque[3] */
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <math.h>
#include "ModelicaUtilities.h"
#include "cad2mo_collision.c"

void ModelicaError(const char* string) {
    fprintf(stderr, "ModelicaError: %s\n", string);
    exit(2);
}

static int read_doubles(double* x, int n) {
    int i;
    for (i = 0; i < n; i++) {
        if (scanf("%lf", &x[i]) != 1) {
            return 0;
        }
    }
    return 1;
}

static int query(void) {
    int na, nb;
    double ra, rb;
    while (scanf("%d %lf", &na, &ra) == 2) {
        double *va, *vb, pa_[12], pb_[12], dist, pa[3], pb[3], n[3];
        int ok;
        if (na < 1 || na > 100000) {
            return 1;
        }
        va = (double*)malloc(sizeof(double) * 3 * (size_t)na);
        if (va == NULL || !read_doubles(va, 3 * na) || !read_doubles(pa_, 12)) {
            return 1;
        }
        if (scanf("%d %lf", &nb, &rb) != 2 || nb < 1 || nb > 100000) {
            return 1;
        }
        vb = (double*)malloc(sizeof(double) * 3 * (size_t)nb);
        if (vb == NULL || !read_doubles(vb, 3 * nb) || !read_doubles(pb_, 12)) {
            return 1;
        }
        ok = cad2mo_collision_query(va, na, ra, pa_, pa_ + 3, vb, nb, rb, pb_, pb_ + 3, &dist, pa, pb, n);
        printf("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g\n", ok, dist, pa[0], pa[1], pa[2], pb[0],
               pb[1], pb[2], n[0], n[1], n[2]);
        free(va);
        free(vb);
    }
    return 0;
}

static int eval(void) {
    int na, nb;
    double ra, rb;
    while (scanf("%d %lf", &na, &ra) == 2) {
        double *v, pa_[12], pb_[12], dist, pa[3], pb[3], n[3], vel[12], law[3];
        double r_0[6], R_T[18], v_0[6], w_a[6], force[6], torque[6], radii[2], st[2], re[2] = {1.0, 1.0}, fr[2];
        int ok, i, partBody[2] = {1, 2}, partVertices[2], checked[4] = {0, 1, 0, 0};
        void* world;
        if (na < 1 || na > 100000) {
            return 1;
        }
        v = (double*)malloc(sizeof(double) * 3 * (size_t)(na + 100000));
        if (v == NULL || !read_doubles(v, 3 * na) || !read_doubles(pa_, 12)) {
            return 1;
        }
        if (scanf("%d %lf", &nb, &rb) != 2 || nb < 1 || nb > 100000) {
            return 1;
        }
        if (!read_doubles(v + 3 * na, 3 * nb) || !read_doubles(pb_, 12) || !read_doubles(vel, 12) || !read_doubles(law, 3)) {
            return 1;
        }
        ok = cad2mo_collision_query(v, na, ra, pa_, pa_ + 3, v + 3 * na, nb, rb, pb_, pb_ + 3, &dist, pa, pb, n);
        for (i = 0; i < 3; i++) {
            r_0[i] = pa_[i];
            r_0[3 + i] = pb_[i];
            v_0[i] = vel[i];
            w_a[i] = vel[3 + i];
            v_0[3 + i] = vel[6 + i];
            w_a[3 + i] = vel[9 + i];
        }
        for (i = 0; i < 9; i++) {
            R_T[i] = pa_[3 + i];
            R_T[9 + i] = pb_[3 + i];
        }
        radii[0] = ra;
        radii[1] = rb;
        partVertices[0] = na;
        partVertices[1] = nb;
        st[0] = st[1] = law[0] * pow(2.0, 1.5);
        fr[0] = fr[1] = law[1];
        world = cad2mo_collision_open(2, 2, partBody, partVertices, radii, na + nb, v, st, re, fr, 1.5, law[2], 1e-3);
        cad2mo_collision_eval(world, r_0, R_T, v_0, w_a, checked, 2, force, torque);
        cad2mo_collision_close(world);
        printf("%d %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g %.17g", ok, dist, pa[0], pa[1], pa[2], pb[0], pb[1],
               pb[2], n[0], n[1], n[2]);
        for (i = 0; i < 6; i++) {
            printf(" %.17g", force[i]);
        }
        for (i = 0; i < 6; i++) {
            printf(" %.17g", torque[i]);
        }
        printf("\n");
        free(v);
    }
    return 0;
}

static int drop(int argc, char** argv) {
    /* body 1: the box [-1,1]x[-1,1]x[-1,0] at rest; body 2: the sphere */
    static const double box[24] = {-1, -1, -1, 1, -1, -1, -1, 1, -1, 1, 1, -1, -1, -1, 0, 1, -1, 0, -1, 1, 0, 1, 1, 0};
    double e, K, ne, m, radius, h, dt, t = 0.0, g = 9.81;
    double vertices[27], radii[2], stiffness[2], restitution[2], friction[2];
    int partBody[2] = {1, 2}, partVertices[2] = {8, 1}, checked[4] = {0, 1, 1, 0};
    double r_0[6] = {0, 0, 0, 0, 0, 0}, R_T[18], v_0[6] = {0, 0, 0, 0, 0, 0}, w_a[6] = {0, 0, 0, 0, 0, 0};
    double force[6], torque[6], v_in = 0.0, apex;
    int in_contact = 0, bounces = 0, i;
    void* world;
    if (argc < 9) {
        return 1;
    }
    e = atof(argv[2]);
    K = atof(argv[3]);
    ne = atof(argv[4]);
    m = atof(argv[5]);
    radius = atof(argv[6]);
    h = atof(argv[7]);
    dt = atof(argv[8]);
    memcpy(vertices, box, sizeof(box));
    vertices[24] = vertices[25] = vertices[26] = 0.0;
    radii[0] = 0.0;
    radii[1] = radius;
    for (i = 0; i < 2; i++) {
        stiffness[i] = K;
        restitution[i] = e;
        friction[i] = 0.5;
    }
    for (i = 0; i < 18; i++) {
        R_T[i] = (i % 9 == 0 || i % 9 == 4 || i % 9 == 8) ? 1.0 : 0.0;
    }
    world = cad2mo_collision_open(2, 2, partBody, partVertices, radii, 9, vertices, stiffness, restitution, friction, ne,
                                  1e-3, 1e-3);
    r_0[5] = radius + h;
    apex = h;
    while (bounces < 3 && t < 10.0) {
        double a;
        int touching;
        cad2mo_collision_eval(world, r_0, R_T, v_0, w_a, checked, 2, force, torque);
        touching = cad2mo_collision_contacts(world);
        if (touching && !in_contact) {
            in_contact = 1;
            v_in = -v_0[5];
        } else if (!touching && in_contact) {
            in_contact = 0;
            apex = 0.0;
            bounces++;
            printf("%.17g %.17g ", v_in, v_0[5]);
        }
        if (!in_contact && bounces > 0 && v_0[5] <= 0.0 && apex == 0.0) {
            apex = r_0[5] - radius;
            printf("%.17g\n", apex);
        }
        a = force[5] / m - g;
        v_0[5] += a * dt;
        r_0[5] += v_0[5] * dt;
        t += dt;
    }
    if (bounces > 0 && apex == 0.0) {
        printf("0\n");
    }
    cad2mo_collision_close(world);
    return 0;
}

static int load(int argc, char** argv) {
    int n = argc - 3, i, k, parts, vertices, checkedPairs = 0;
    double *r_0, *R_T, *v_0, *force, *torque, st, re, fr;
    double *stiffness, *restitution, *friction;
    c2mc_world* w;
    if (n < 1) {
        return 1;
    }
    r_0 = (double*)calloc((size_t)n * 3, sizeof(double));
    R_T = (double*)calloc((size_t)n * 9, sizeof(double));
    v_0 = (double*)calloc((size_t)n * 3, sizeof(double));
    force = (double*)calloc((size_t)n * 3, sizeof(double));
    torque = (double*)calloc((size_t)n * 3, sizeof(double));
    stiffness = (double*)calloc((size_t)n, sizeof(double));
    restitution = (double*)calloc((size_t)n, sizeof(double));
    friction = (double*)calloc((size_t)n, sizeof(double));
    if (!r_0 || !R_T || !v_0 || !force || !torque || !stiffness || !restitution || !friction) {
        return 1;
    }
    st = 1e7;
    re = 0.5;
    fr = 0.3;
    for (i = 0; i < n; i++) {
        stiffness[i] = st;
        restitution[i] = re;
        friction[i] = fr;
        if (!read_doubles(r_0 + 3 * i, 3) || !read_doubles(R_T + 9 * i, 9)) {
            return 1;
        }
    }
    w = (c2mc_world*)cad2mo_collision_load(argv[2], n, (const char**)(argv + 3), 0, NULL, stiffness, restitution, friction, 1.5, 0.01, 0.01);
    parts = w->nParts;
    vertices = w->nVertices;
    for (i = 0; i < n; i++) {
        for (k = i + 1; k < n; k++) {
            checkedPairs += w->checked[i * n + k];
        }
    }
    cad2mo_collision_forces(w, r_0, R_T, v_0, v_0, n, force, torque);
    printf("%d %d %d %d\n", parts, vertices, checkedPairs, cad2mo_collision_contacts(w));
    for (i = 0; i < n; i++) {
        printf("%.17g %.17g %.17g %.17g %.17g %.17g\n", force[3 * i], force[3 * i + 1], force[3 * i + 2], torque[3 * i], torque[3 * i + 1], torque[3 * i + 2]);
    }
    cad2mo_collision_close(w);
    free(r_0);
    free(R_T);
    free(v_0);
    free(force);
    free(torque);
    free(stiffness);
    free(restitution);
    free(friction);
    return 0;
}

int main(int argc, char** argv) {
    if (argc >= 3 && strcmp(argv[1], "load") == 0) {
        return load(argc, argv);
    }
    if (argc >= 2 && strcmp(argv[1], "query") == 0) {
        return query();
    }
    if (argc >= 2 && strcmp(argv[1], "eval") == 0) {
        return eval();
    }
    if (argc >= 2 && strcmp(argv[1], "drop") == 0) {
        return drop(argc, argv);
    }
    fprintf(stderr, "usage: harness query | harness eval | harness drop e stiffness exponent mass radius height dt | harness load FILE NAME...\n");
    return 1;
}
