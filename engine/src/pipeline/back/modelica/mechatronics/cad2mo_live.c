/* cad2mo live view sender, protocol version 1 (cad2mo's docs/live-protocol.md).
 *
 * Sends the poses of a model's bodies to a cad2mo service as UDP datagrams, one frame per call,
 * never blocking the simulation: a send that the network refuses is counted and skipped. Used by
 * <Pkg>.Components.Visualization.LiveView through Modelica's external "C" interface; plain C99,
 * no library to link (on Windows, ws2_32.dll is loaded at run time). Every function is static:
 * a tool may include this file in several translation units.
 *
 * Written by cad2mo; MIT licence. */
#ifndef CAD2MO_LIVE_C
#define CAD2MO_LIVE_C

#if !defined(_WIN32) && !defined(_POSIX_C_SOURCE)
#define _POSIX_C_SOURCE 200809L
#endif
#include <stddef.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <stdio.h>
#include "ModelicaUtilities.h"

#if defined(_WIN32)
#include <winsock2.h>
#include <ws2tcpip.h>
#include <windows.h>
#else
#include <sys/types.h>
#include <sys/socket.h>
#include <netdb.h>
#include <unistd.h>
#include <fcntl.h>
#include <time.h>
#include <errno.h>
#endif

#define C2ML_HEADER 64
#define C2ML_BODY 48
#define C2ML_TAG 32
#define C2ML_MAX_BODIES 1024

/* ---- SHA-256 and HMAC-SHA256 (FIPS 180-4, RFC 2104) ---- */

typedef struct {
    uint32_t h[8];
    uint64_t bytes;
    unsigned char block[64];
    size_t used;
} c2ml_sha256;

static const uint32_t c2ml_k[64] = {
    0x428a2f98u, 0x71374491u, 0xb5c0fbcfu, 0xe9b5dba5u, 0x3956c25bu, 0x59f111f1u, 0x923f82a4u, 0xab1c5ed5u,
    0xd807aa98u, 0x12835b01u, 0x243185beu, 0x550c7dc3u, 0x72be5d74u, 0x80deb1feu, 0x9bdc06a7u, 0xc19bf174u,
    0xe49b69c1u, 0xefbe4786u, 0x0fc19dc6u, 0x240ca1ccu, 0x2de92c6fu, 0x4a7484aau, 0x5cb0a9dcu, 0x76f988dau,
    0x983e5152u, 0xa831c66du, 0xb00327c8u, 0xbf597fc7u, 0xc6e00bf3u, 0xd5a79147u, 0x06ca6351u, 0x14292967u,
    0x27b70a85u, 0x2e1b2138u, 0x4d2c6dfcu, 0x53380d13u, 0x650a7354u, 0x766a0abbu, 0x81c2c92eu, 0x92722c85u,
    0xa2bfe8a1u, 0xa81a664bu, 0xc24b8b70u, 0xc76c51a3u, 0xd192e819u, 0xd6990624u, 0xf40e3585u, 0x106aa070u,
    0x19a4c116u, 0x1e376c08u, 0x2748774cu, 0x34b0bcb5u, 0x391c0cb3u, 0x4ed8aa4au, 0x5b9cca4fu, 0x682e6ff3u,
    0x748f82eeu, 0x78a5636fu, 0x84c87814u, 0x8cc70208u, 0x90befffau, 0xa4506cebu, 0xbef9a3f7u, 0xc67178f2u};

#define C2ML_ROR(x, n) (((x) >> (n)) | ((x) << (32 - (n))))

static void c2ml_sha256_block(c2ml_sha256* s, const unsigned char* p) {
    uint32_t w[64], a, b, c, d, e, f, g, h;
    int i;
    for (i = 0; i < 16; i++) {
        w[i] = ((uint32_t)p[4 * i] << 24) | ((uint32_t)p[4 * i + 1] << 16) | ((uint32_t)p[4 * i + 2] << 8) | (uint32_t)p[4 * i + 3];
    }
    for (i = 16; i < 64; i++) {
        uint32_t s0 = C2ML_ROR(w[i - 15], 7) ^ C2ML_ROR(w[i - 15], 18) ^ (w[i - 15] >> 3);
        uint32_t s1 = C2ML_ROR(w[i - 2], 17) ^ C2ML_ROR(w[i - 2], 19) ^ (w[i - 2] >> 10);
        w[i] = w[i - 16] + s0 + w[i - 7] + s1;
    }
    a = s->h[0]; b = s->h[1]; c = s->h[2]; d = s->h[3];
    e = s->h[4]; f = s->h[5]; g = s->h[6]; h = s->h[7];
    for (i = 0; i < 64; i++) {
        uint32_t t1 = h + (C2ML_ROR(e, 6) ^ C2ML_ROR(e, 11) ^ C2ML_ROR(e, 25)) + ((e & f) ^ (~e & g)) + c2ml_k[i] + w[i];
        uint32_t t2 = (C2ML_ROR(a, 2) ^ C2ML_ROR(a, 13) ^ C2ML_ROR(a, 22)) + ((a & b) ^ (a & c) ^ (b & c));
        h = g; g = f; f = e; e = d + t1;
        d = c; c = b; b = a; a = t1 + t2;
    }
    s->h[0] += a; s->h[1] += b; s->h[2] += c; s->h[3] += d;
    s->h[4] += e; s->h[5] += f; s->h[6] += g; s->h[7] += h;
}

static void c2ml_sha256_init(c2ml_sha256* s) {
    static const uint32_t h0[8] = {0x6a09e667u, 0xbb67ae85u, 0x3c6ef372u, 0xa54ff53au,
                                   0x510e527fu, 0x9b05688cu, 0x1f83d9abu, 0x5be0cd19u};
    memcpy(s->h, h0, sizeof h0);
    s->bytes = 0;
    s->used = 0;
}

static void c2ml_sha256_update(c2ml_sha256* s, const unsigned char* p, size_t n) {
    s->bytes += n;
    while (n > 0) {
        size_t take = 64 - s->used;
        if (take > n) take = n;
        memcpy(s->block + s->used, p, take);
        s->used += take;
        p += take;
        n -= take;
        if (s->used == 64) {
            c2ml_sha256_block(s, s->block);
            s->used = 0;
        }
    }
}

static void c2ml_sha256_final(c2ml_sha256* s, unsigned char out[32]) {
    uint64_t bits = s->bytes * 8u;
    unsigned char pad = 0x80, zero = 0, len[8];
    int i;
    c2ml_sha256_update(s, &pad, 1);
    while (s->used != 56) c2ml_sha256_update(s, &zero, 1);
    for (i = 0; i < 8; i++) len[i] = (unsigned char)(bits >> (56 - 8 * i));
    c2ml_sha256_update(s, len, 8);
    for (i = 0; i < 8; i++) {
        out[4 * i] = (unsigned char)(s->h[i] >> 24);
        out[4 * i + 1] = (unsigned char)(s->h[i] >> 16);
        out[4 * i + 2] = (unsigned char)(s->h[i] >> 8);
        out[4 * i + 3] = (unsigned char)s->h[i];
    }
}

static void c2ml_sha256_of(const unsigned char* p, size_t n, unsigned char out[32]) {
    c2ml_sha256 s;
    c2ml_sha256_init(&s);
    c2ml_sha256_update(&s, p, n);
    c2ml_sha256_final(&s, out);
}

/* HMAC-SHA256 with a 32-byte key (shorter than the block: padded with zeros). */
static void c2ml_hmac(const unsigned char key[32], const unsigned char* msg, size_t n, unsigned char out[32]) {
    unsigned char pad[64], inner[32];
    c2ml_sha256 s;
    int i;
    for (i = 0; i < 64; i++) pad[i] = (unsigned char)((i < 32 ? key[i] : 0) ^ 0x36);
    c2ml_sha256_init(&s);
    c2ml_sha256_update(&s, pad, 64);
    c2ml_sha256_update(&s, msg, n);
    c2ml_sha256_final(&s, inner);
    for (i = 0; i < 64; i++) pad[i] = (unsigned char)((i < 32 ? key[i] : 0) ^ 0x5c);
    c2ml_sha256_init(&s);
    c2ml_sha256_update(&s, pad, 64);
    c2ml_sha256_update(&s, inner, 32);
    c2ml_sha256_final(&s, out);
}

/* ---- sockets ---- */

#if defined(_WIN32)
typedef SOCKET c2ml_socket;
#define C2ML_NO_SOCKET INVALID_SOCKET
typedef int(WSAAPI* c2ml_wsastartup_t)(WORD, LPWSADATA);
typedef SOCKET(WSAAPI* c2ml_socket_t)(int, int, int);
typedef int(WSAAPI* c2ml_sendto_t)(SOCKET, const char*, int, int, const struct sockaddr*, int);
typedef int(WSAAPI* c2ml_close_t)(SOCKET);
typedef int(WSAAPI* c2ml_getaddrinfo_t)(PCSTR, PCSTR, const ADDRINFOA*, PADDRINFOA*);
typedef void(WSAAPI* c2ml_freeaddrinfo_t)(PADDRINFOA);
typedef int(WSAAPI* c2ml_ioctl_t)(SOCKET, long, u_long*);
static struct {
    HMODULE dll;
    c2ml_socket_t socket;
    c2ml_sendto_t sendto;
    c2ml_close_t close;
    c2ml_getaddrinfo_t getaddrinfo;
    c2ml_freeaddrinfo_t freeaddrinfo;
    c2ml_ioctl_t ioctl;
} c2ml_ws;

static int c2ml_net_init(void) {
    WSADATA data;
    c2ml_wsastartup_t startup;
    if (c2ml_ws.dll) return 1;
    c2ml_ws.dll = LoadLibraryA("ws2_32.dll");
    if (!c2ml_ws.dll) return 0;
    startup = (c2ml_wsastartup_t)(void*)GetProcAddress(c2ml_ws.dll, "WSAStartup");
    c2ml_ws.socket = (c2ml_socket_t)(void*)GetProcAddress(c2ml_ws.dll, "socket");
    c2ml_ws.sendto = (c2ml_sendto_t)(void*)GetProcAddress(c2ml_ws.dll, "sendto");
    c2ml_ws.close = (c2ml_close_t)(void*)GetProcAddress(c2ml_ws.dll, "closesocket");
    c2ml_ws.getaddrinfo = (c2ml_getaddrinfo_t)(void*)GetProcAddress(c2ml_ws.dll, "getaddrinfo");
    c2ml_ws.freeaddrinfo = (c2ml_freeaddrinfo_t)(void*)GetProcAddress(c2ml_ws.dll, "freeaddrinfo");
    c2ml_ws.ioctl = (c2ml_ioctl_t)(void*)GetProcAddress(c2ml_ws.dll, "ioctlsocket");
    if (!startup || !c2ml_ws.socket || !c2ml_ws.sendto || !c2ml_ws.close || !c2ml_ws.getaddrinfo ||
        !c2ml_ws.freeaddrinfo || !c2ml_ws.ioctl || startup(MAKEWORD(2, 2), &data) != 0) {
        FreeLibrary(c2ml_ws.dll);
        c2ml_ws.dll = NULL;
        return 0;
    }
    return 1;
}
#define c2ml_sys_socket(a, b, c) c2ml_ws.socket(a, b, c)
#define c2ml_sys_close(s) c2ml_ws.close(s)
#define c2ml_sys_getaddrinfo(h, p, hints, res) c2ml_ws.getaddrinfo(h, p, hints, res)
#define c2ml_sys_freeaddrinfo(r) c2ml_ws.freeaddrinfo(r)
static int c2ml_nonblocking(c2ml_socket s) {
    u_long on = 1;
    return c2ml_ws.ioctl(s, FIONBIO, &on) == 0;
}
static long c2ml_sys_sendto(c2ml_socket s, const unsigned char* p, size_t n, const struct sockaddr* a, size_t alen) {
    return c2ml_ws.sendto(s, (const char*)p, (int)n, 0, a, (int)alen);
}
static double c2ml_now(void) {
    LARGE_INTEGER f, c;
    QueryPerformanceFrequency(&f);
    QueryPerformanceCounter(&c);
    return (double)c.QuadPart / (double)f.QuadPart;
}
static void c2ml_sleep(double s) {
    if (s > 0) Sleep((DWORD)(s * 1000.0));
}
#else
typedef int c2ml_socket;
#define C2ML_NO_SOCKET (-1)
static int c2ml_net_init(void) { return 1; }
#define c2ml_sys_socket(a, b, c) socket(a, b, c)
#define c2ml_sys_close(s) close(s)
#define c2ml_sys_getaddrinfo(h, p, hints, res) getaddrinfo(h, p, hints, res)
#define c2ml_sys_freeaddrinfo(r) freeaddrinfo(r)
static int c2ml_nonblocking(c2ml_socket s) {
    int flags = fcntl(s, F_GETFL, 0);
    return flags >= 0 && fcntl(s, F_SETFL, flags | O_NONBLOCK) == 0;
}
static long c2ml_sys_sendto(c2ml_socket s, const unsigned char* p, size_t n, const struct sockaddr* a, size_t alen) {
    return (long)sendto(s, p, n, 0, a, (socklen_t)alen);
}
static double c2ml_now(void) {
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)t.tv_sec + 1e-9 * (double)t.tv_nsec;
}
static void c2ml_sleep(double s) {
    struct timespec t;
    if (s <= 0) return;
    t.tv_sec = (time_t)s;
    t.tv_nsec = (long)((s - (double)t.tv_sec) * 1e9);
    while (nanosleep(&t, &t) != 0 && errno == EINTR) {
    }
}
#endif

/* ---- the sender ---- */

typedef struct {
    c2ml_socket sock;
    struct sockaddr_storage addr;
    size_t addr_len;
    int n;
    int auth;
    int real_time;
    unsigned char key[32];
    unsigned char* frame;
    size_t frame_len;
    uint32_t seq;
    double wall0, time0;
    int paced;
    long failed;
    int warned;
} cad2mo_live;

static void c2ml_put16(unsigned char* p, uint32_t v) { p[0] = (unsigned char)v; p[1] = (unsigned char)(v >> 8); }
static void c2ml_put32(unsigned char* p, uint32_t v) {
    int i;
    for (i = 0; i < 4; i++) p[i] = (unsigned char)(v >> (8 * i));
}
static void c2ml_put_f32(unsigned char* p, double x) {
    float f = (float)x;
    uint32_t v;
    memcpy(&v, &f, 4);
    c2ml_put32(p, v);
}
static void c2ml_put_f64(unsigned char* p, double x) {
    uint64_t v;
    int i;
    memcpy(&v, &x, 8);
    for (i = 0; i < 8; i++) p[i] = (unsigned char)(v >> (8 * i));
}

static int c2ml_hex(char c) {
    if (c >= '0' && c <= '9') return c - '0';
    if (c >= 'a' && c <= 'f') return c - 'a' + 10;
    if (c >= 'A' && c <= 'F') return c - 'A' + 10;
    return -1;
}

/* Parses `len` bytes of hex digits, skipping '-' (for UUIDs); 0 unless exactly that many. */
static int c2ml_parse_hex(const char* text, unsigned char* out, size_t len) {
    size_t k = 0;
    int hi = -1;
    for (; *text; text++) {
        int v;
        if (*text == '-') continue;
        v = c2ml_hex(*text);
        if (v < 0 || k >= len) return 0;
        if (hi < 0) {
            hi = v;
        } else {
            out[k++] = (unsigned char)(hi * 16 + v);
            hi = -1;
        }
    }
    return k == len && hi < 0;
}

/* Opens a sender to host:port for `nBodies` bodies of model `model` (UUID) version `version`,
 * whose body list hashes to `layout` (16 hex digits). `token` may be empty. Never fails the
 * simulation: a problem is reported once as a warning and the sender then sends nothing. */
static void* cad2mo_live_open(const char* host, int port, const char* model, int version, const char* layout,
                       const char* token, int nBodies, int realTime) {
    cad2mo_live* s;
    struct addrinfo hints, *res = NULL;
    char service[16];
    unsigned char* h;
    uint32_t run;
    int rc;
    s = (cad2mo_live*)calloc(1, sizeof(cad2mo_live));
    if (!s) {
        ModelicaError("cad2mo live view: out of memory");
        return NULL;
    }
    s->sock = C2ML_NO_SOCKET;
    s->n = nBodies;
    s->real_time = realTime != 0;
    if (nBodies < 1 || nBodies > C2ML_MAX_BODIES) {
        ModelicaFormatWarning("cad2mo live view: %d bodies (at most %d fit a frame): the live view is off\n", nBodies, C2ML_MAX_BODIES);
        return s;
    }
    if (port < 1 || port > 65535) {
        ModelicaFormatWarning("cad2mo live view: port %d is not a UDP port: the live view is off\n", port);
        return s;
    }
    s->frame_len = C2ML_HEADER + (size_t)C2ML_BODY * (size_t)nBodies;
    s->auth = token != NULL && token[0] != '\0';
    s->frame = (unsigned char*)calloc(1, s->frame_len + C2ML_TAG);
    if (!s->frame) {
        ModelicaError("cad2mo live view: out of memory");
        return s;
    }
    h = s->frame;
    memcpy(h, "C2ML", 4);
    h[4] = 1;
    h[5] = (unsigned char)(s->auth ? 1 : 0);
    c2ml_put16(h + 6, C2ML_HEADER);
    if (!c2ml_parse_hex(model, h + 8, 16) || !c2ml_parse_hex(layout, h + 28, 8)) {
        ModelicaFormatWarning("cad2mo live view: model id \"%s\" or layout \"%s\" is malformed: the live view is off\n", model, layout);
        free(s->frame);
        s->frame = NULL;
        return s;
    }
    c2ml_put32(h + 24, (uint32_t)version);
    c2ml_put32(h + 48, (uint32_t)nBodies);
    /* The run id tells two runs apart; it needs to differ, not to be secret. */
    run = (uint32_t)(c2ml_now() * 1e6) ^ (uint32_t)(size_t)s ^ ((uint32_t)rand() << 16);
    c2ml_put32(h + 52, run);
    if (s->auth) {
        unsigned char id[32];
        c2ml_sha256_of((const unsigned char*)token, strlen(token), s->key);
        c2ml_sha256_of(s->key, 32, id);
        memcpy(h + 56, id, 8);
    }
    if (!c2ml_net_init()) {
        ModelicaFormatWarning("cad2mo live view: the network library could not be loaded: the live view is off\n");
        return s;
    }
    memset(&hints, 0, sizeof hints);
    hints.ai_family = AF_UNSPEC;
    hints.ai_socktype = SOCK_DGRAM;
    snprintf(service, sizeof service, "%d", port);
    rc = c2ml_sys_getaddrinfo(host, service, &hints, &res);
    if (rc != 0 || res == NULL || res->ai_addrlen > sizeof s->addr) {
        ModelicaFormatWarning("cad2mo live view: host \"%s\" was not found: the live view is off\n", host);
        if (res) c2ml_sys_freeaddrinfo(res);
        return s;
    }
    s->sock = c2ml_sys_socket(res->ai_family, SOCK_DGRAM, 0);
    memcpy(&s->addr, res->ai_addr, res->ai_addrlen);
    s->addr_len = (size_t)res->ai_addrlen;
    c2ml_sys_freeaddrinfo(res);
    if (s->sock == C2ML_NO_SOCKET || !c2ml_nonblocking(s->sock)) {
        ModelicaFormatWarning("cad2mo live view: no UDP socket could be opened: the live view is off\n");
        if (s->sock != C2ML_NO_SOCKET) c2ml_sys_close(s->sock);
        s->sock = C2ML_NO_SOCKET;
    }
    return s;
}

/* Sends one frame: the simulated time, then per body r_0 (nBodies x 3, row-major) and R.T
 * (nBodies x 3 x 3, row-major). `final` marks the last frame of the run. Returns the number of
 * frames sent so far by this sender. With real-time pacing, first waits until wall-clock time
 * since the first frame catches up with simulated time. */
static int cad2mo_live_send(void* handle, double time, const double* r0, const double* RT, int nBodies, int final) {
    cad2mo_live* s = (cad2mo_live*)handle;
    unsigned char* p;
    long sent;
    size_t len;
    int i, k;
    if (!s || !s->frame || s->sock == C2ML_NO_SOCKET) return 0;
    if (nBodies != s->n) {
        if (!s->warned) ModelicaFormatWarning("cad2mo live view: %d bodies given, %d expected: frames are not sent\n", nBodies, s->n);
        s->warned = 1;
        return (int)s->seq;
    }
    if (s->real_time) {
        double now = c2ml_now();
        if (!s->paced) {
            s->wall0 = now;
            s->time0 = time;
            s->paced = 1;
        } else {
            c2ml_sleep((time - s->time0) - (now - s->wall0));
        }
    }
    p = s->frame;
    p[5] = (unsigned char)((s->auth ? 1 : 0) | (final ? 2 : 0));
    c2ml_put32(p + 36, s->seq);
    c2ml_put_f64(p + 40, time);
    p += C2ML_HEADER;
    for (i = 0; i < s->n; i++) {
        for (k = 0; k < 3; k++) c2ml_put_f32(p + 4 * k, r0[3 * i + k]);
        for (k = 0; k < 9; k++) c2ml_put_f32(p + 12 + 4 * k, RT[9 * i + k]);
        p += C2ML_BODY;
    }
    len = s->frame_len;
    if (s->auth) {
        c2ml_hmac(s->key, s->frame, s->frame_len, s->frame + s->frame_len);
        len += C2ML_TAG;
    }
    sent = c2ml_sys_sendto(s->sock, s->frame, len, (const struct sockaddr*)&s->addr, s->addr_len);
    if (sent != (long)len) s->failed++;
    s->seq++;
    return (int)s->seq;
}

/* Frames whose send failed (the network refused them; nothing waits for a viewer). */
static int cad2mo_live_failed(void* handle) {
    cad2mo_live* s = (cad2mo_live*)handle;
    return s ? (int)s->failed : 0;
}

static void cad2mo_live_close(void* handle) {
    cad2mo_live* s = (cad2mo_live*)handle;
    if (!s) return;
    if (s->sock != C2ML_NO_SOCKET) c2ml_sys_close(s->sock);
    free(s->frame);
    free(s);
}

#endif /* CAD2MO_LIVE_C */
