/* Drives the live view sender a package ships (Resources/Include/cad2mo_live.c) the way the
 * Modelica block LiveView does: open, one send per sample (the last marked final), close.
 *
 *   harness HOST PORT MODEL_UUID VERSION LAYOUT_HEX TOKEN REALTIME < samples.txt
 *
 * TOKEN is "-" for none; REALTIME 1 paces frames at simulated time. Each stdin line is the time
 * followed by 12 numbers per body: r_0 x y z, then R.T row by row. Prints "sent N failed F". */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "ModelicaUtilities.h"
#include "cad2mo_live.c"

void ModelicaError(const char* string) {
    fprintf(stderr, "ModelicaError: %s\n", string);
    exit(3);
}

void ModelicaFormatWarning(const char* format, ...) {
    va_list ap;
    va_start(ap, format);
    fputs("ModelicaWarning: ", stderr);
    vfprintf(stderr, format, ap);
    va_end(ap);
}

/* Reads one line of numbers into *row (grown as needed); returns how many, -1 at the end. */
static int read_row(double** row, size_t* cap) {
    static char line[1 << 20];
    char *p, *end;
    size_t k = 0;
    if (!fgets(line, sizeof line, stdin)) return -1;
    for (p = line;; p = end) {
        double v = strtod(p, &end);
        if (end == p) break;
        if (k == *cap) {
            *cap = *cap ? 2 * *cap : 64;
            *row = (double*)realloc(*row, *cap * sizeof(double));
            if (!*row) exit(4);
        }
        (*row)[k++] = v;
    }
    return (int)k;
}

int main(int argc, char** argv) {
    double *row = NULL, *next = NULL;
    size_t cap = 0, next_cap = 0;
    int k, n, count = 0;
    void* s;
    if (argc != 8) {
        fprintf(stderr, "usage: harness HOST PORT MODEL_UUID VERSION LAYOUT_HEX TOKEN REALTIME < samples\n");
        return 2;
    }
    k = read_row(&row, &cap);
    if (k < 13 || (k - 1) % 12 != 0) {
        fprintf(stderr, "the first sample has %d numbers: want 1 + 12 per body\n", k);
        return 2;
    }
    n = (k - 1) / 12;
    s = cad2mo_live_open(argv[1], atoi(argv[2]), argv[3], atoi(argv[4]), argv[5],
                         strcmp(argv[6], "-") == 0 ? "" : argv[6], n, atoi(argv[7]));
    for (;;) {
        int m = read_row(&next, &next_cap);
        int last = m < 0;
        if (!last && m != k) {
            fprintf(stderr, "sample %d has %d numbers, the first had %d\n", count + 2, m, k);
            return 2;
        }
        {
            /* Split the row the way Modelica passes r_0[n,3] and R_T[n,3,3]: two arrays. */
            double* r0 = (double*)malloc(sizeof(double) * 3 * (size_t)n);
            double* rt = (double*)malloc(sizeof(double) * 9 * (size_t)n);
            int b, j;
            if (!r0 || !rt) return 4;
            for (b = 0; b < n; b++) {
                for (j = 0; j < 3; j++) r0[3 * b + j] = row[1 + 12 * b + j];
                for (j = 0; j < 9; j++) rt[9 * b + j] = row[1 + 12 * b + 3 + j];
            }
            count = cad2mo_live_send(s, row[0], r0, rt, n, last);
            free(r0);
            free(rt);
        }
        if (last) break;
        {
            double* t = row;
            size_t c = cap;
            row = next;
            cap = next_cap;
            next = t;
            next_cap = c;
        }
    }
    printf("sent %d failed %d\n", count, cad2mo_live_failed(s));
    cad2mo_live_close(s);
    free(row);
    free(next);
    return 0;
}
