// tb_verilator.cpp - every RTL kernel against the C specification, bit for
// bit: the test top (rtl_all, generated from kernels.txt) holds every kernel
// on one broadcast input bus, so each clock's input vector goes through all
// of them, and every valid output of every kernel is compared with
// facet_<kernel>_fx_fast (libfacet) at that vector.
//   tb_verilator [--random N] [--seed S] [--vectors DIR]
// Phases: the golden vectors of DIR/<kernel>.hex (`facet vectors --format
// fx_fast --hex`; their outputs are also compared with the C, so a stale
// file fails), each kernel's file in turn with a new sample every clock;
// then N random vectors, the first half with a new sample every clock, the
// second with bubbles (in_valid low 1 clock in 8) and reset pulses of 1-3
// clocks mid-stream.  The valid bits are checked against a model of the
// stated latency (kernels.txt) with the synchronous reset: out_valid must be
// in_valid delayed by exactly that many clocks, cleared by every reset, and
// the data in order.  Inputs, per word: any int32 (1 in 16), special
// patterns (INT32_MIN/MAX, 0, +-1, ...; 1 in 16), a domain edge +-4 (1 in
// 8), a wide band just outside the domains (1 in 16), else in the domain of
// one kernel (a different kernel every 1024 clocks).
// Prints one line per kernel and "rtl_verilator: N passed, N failed, 0 skipped".
#include <cinttypes>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "Vrtl_all.h"
#include "verilated.h"
#include "facet/fx.h"

namespace {

struct Kernel {
    const char *name;
    int n_in, bits, outs, lat, slot;
    const facet_fx_kernel *fk;
    uint64_t compared, edges, bad, first_in, first_out;
};

Kernel kernels[] = {
#define RTL_K(name, n_in, bits, outs, lat, slot) {#name, n_in, bits, outs, lat, slot, nullptr, 0, 0, 0, 0, 0},
#include "rtl_kernels.h"
#undef RTL_K
};
const int NK = sizeof kernels / sizeof kernels[0];
const int NX = 10;

struct Sample {
    int32_t x[NX];
    bool valid;
    int file_k; // the kernel whose golden vector this is, or -1
    uint64_t file_out;
};

uint64_t rng = 1;
uint64_t next_u64()
{
    uint64_t z = (rng += 0x9E3779B97F4A7C15ull);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ull;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBull;
    return z ^ (z >> 31);
}

const int32_t specials[] = {INT32_MIN, INT32_MIN + 1, INT32_MAX, INT32_MAX - 1, -1, 0, 1, 2,
                            -32768, -32767, -32769, 32767, 32768, 32769, 65535, 65536,
                            65537, 131072, 131073, 127, 128, 129, 31, 32, 33, 16384, -16384};
const int32_t edges[] = {-32768, 0, 32, 128, 32768, 131072};

int32_t draw(int j, int focus)
{
    uint64_t r = next_u64();
    unsigned c = (unsigned)(r & 15);
    r >>= 4;
    if (c == 0)
        return (int32_t)(uint32_t)r;
    if (c == 1)
        return specials[r % (sizeof specials / sizeof specials[0])];
    if (c <= 3)
        return edges[r % 6] + (int32_t)((r >> 8) % 9) - 4;
    if (c == 4)
        return (int32_t)(r % 600001) - 200000;
    const facet_fx_kernel *fk = kernels[focus].fk;
    int jj = fk->n_inputs ? j % fk->n_inputs : 0;
    int64_t lo = fk->lo[jj], hi = fk->hi[jj];
    return (int32_t)(lo + (int64_t)(r % (uint64_t)(hi - lo + 1)));
}

// the C's outputs of kernel k at sample s, one per output slot
void expect(const Kernel &k, const Sample &s, uint64_t out[3])
{
    if (k.outs == 3) {
        int32_t f0[3] = {s.x[4], s.x[6], s.x[8]}, alb[3] = {s.x[5], s.x[7], s.x[9]};
        facet_brdf_hammon_rgb_fx_fast(out, s.x[0], s.x[1], s.x[2], s.x[3], f0, alb);
    } else {
        out[0] = k.fk->fx_fast(s.x);
    }
}

struct Sim {
    Vrtl_all *top;
    uint64_t cycle = 0;
    Sample ring[128];
    uint64_t vmodel[NK] = {};
    int shown = 0;
    uint64_t file_bad = 0;

    explicit Sim(Vrtl_all *t) : top(t) {}

    uint64_t slot_out(int s) const
    {
        return (uint64_t)top->y[2 * s] | (uint64_t)top->y[2 * s + 1] << 32;
    }
    bool slot_valid(int s) const { return (top->ov >> s) & 1; }

    // one clock: present sample s (and rst), rising edge, check every kernel
    void step(const Sample &s, bool rst)
    {
        for (int j = 0; j < NX; j++)
            top->x[j] = (uint32_t)s.x[j];
        top->in_valid = s.valid;
        top->rst = rst;
        top->clk = 1;
        top->eval();
        ring[cycle % 128] = s;
        for (int i = 0; i < NK; i++) {
            Kernel &k = kernels[i];
            uint64_t mask = k.lat >= 64 ? ~0ull : (1ull << k.lat) - 1;
            vmodel[i] = rst ? 0 : ((vmodel[i] << 1) | (s.valid ? 1 : 0)) & mask;
            bool want = (vmodel[i] >> (k.lat - 1)) & 1;
            if (s.valid && !rst && !k.first_in)
                k.first_in = cycle + 1;
            bool got = slot_valid(k.slot);
            if (got && !k.first_out)
                k.first_out = cycle + 1;
            if (got != want) {
                if (k.bad++ < 3)
                    printf("FAIL %s: out_valid %d at clock %" PRIu64 ", the latency-%d model says %d\n", k.name, got,
                           cycle, k.lat, want);
                continue;
            }
            if (!got)
                continue;
            const Sample &in = ring[(cycle + 1 - (uint64_t)k.lat) % 128];
            uint64_t want_out[3];
            expect(k, in, want_out);
            k.compared++;
            if (in.file_k >= 0)
                k.edges++;
            for (int o = 0; o < k.outs; o++) {
                uint64_t g = slot_out(k.slot + o);
                if (k.bits == 32)
                    g &= 0xFFFFFFFFull;
                bool file_mismatch = in.file_k >= 0 &&
                                     (in.file_k == i || (k.outs == 3 && !strcmp(kernels[in.file_k].name, "brdf_hammon"))) &&
                                     g != in.file_out;
                if (g != want_out[o] || file_mismatch) {
                    k.bad++;
                    if (shown++ < 20) {
                        printf("FAIL %s[%d]: rtl %016" PRIx64 " c %016" PRIx64, k.name, o, g, want_out[o]);
                        if (file_mismatch)
                            printf(" golden %016" PRIx64, in.file_out);
                        printf(" at");
                        for (int j = 0; j < k.n_in; j++)
                            printf(" %" PRId32, in.x[j]);
                        printf("\n");
                    }
                }
            }
        }
        top->clk = 0;
        top->eval();
        cycle++;
    }
};

int kernel_index(const char *name)
{
    for (int i = 0; i < NK; i++)
        if (!strcmp(kernels[i].name, name))
            return i;
    return -1;
}

// the golden vectors of kernel i (`facet vectors --hex`), or none
std::vector<Sample> read_vectors(const std::string &dir, int i, int *n_files)
{
    std::vector<Sample> v;
    const Kernel &k = kernels[i];
    if (k.outs != 1)
        return v; // the RGB form is checked on brdf_hammon's file
    std::string path = dir + "/" + k.name + ".hex";
    FILE *f = fopen(path.c_str(), "r");
    if (!f)
        return v;
    ++*n_files;
    char line[512];
    int hexw = k.bits / 4;
    while (fgets(line, sizeof line, f)) {
        if (line[0] == '/' || line[0] == '\n')
            continue;
        Sample s;
        for (int j = 0; j < NX; j++)
            s.x[j] = (int32_t)(uint32_t)next_u64();
        for (int j = 0; j < k.n_in; j++) {
            char w[9];
            memcpy(w, line + 8 * j, 8);
            w[8] = 0;
            s.x[j] = (int32_t)(uint32_t)strtoul(w, nullptr, 16);
        }
        char o[17];
        memcpy(o, line + 8 * k.n_in, (size_t)hexw);
        o[hexw] = 0;
        s.file_out = strtoull(o, nullptr, 16);
        s.valid = true;
        s.file_k = i;
        if (!strcmp(k.name, "brdf_hammon")) { // the RGB form at the same f0, albedo per channel
            s.x[6] = s.x[8] = s.x[4];
            s.x[7] = s.x[9] = s.x[5];
        }
        v.push_back(s);
    }
    fclose(f);
    return v;
}

} // namespace

int main(int argc, char **argv)
{
    uint64_t n_random = 100000, seed = 1;
    std::string vecdir;
    for (int i = 1; i < argc; i++) {
        if (!strcmp(argv[i], "--random") && i + 1 < argc)
            n_random = strtoull(argv[++i], nullptr, 10);
        else if (!strcmp(argv[i], "--seed") && i + 1 < argc)
            seed = strtoull(argv[++i], nullptr, 10);
        else if (!strcmp(argv[i], "--vectors") && i + 1 < argc)
            vecdir = argv[++i];
        else if (argv[i][0] != '+') {
            fprintf(stderr, "usage: tb_verilator [--random N] [--seed S] [--vectors DIR]\n");
            return 2;
        }
    }
    rng = seed;
    for (int i = 0; i < NK; i++) {
        const char *lookup = kernels[i].outs == 3 ? "brdf_hammon" : kernels[i].name;
        kernels[i].fk = facet_fx_kernel_find(lookup);
        if (!kernels[i].fk) {
            printf("ERROR rtl_verilator: %s is not a kernel of libfacet\n", lookup);
            return 1;
        }
    }
    Verilated::commandArgs(argc, argv);
    Vrtl_all *top = new Vrtl_all;
    Sim sim(top);
    top->clk = 0;
    top->rst = 1;
    top->eval();
    Sample idle;
    memset(&idle, 0, sizeof idle);
    idle.file_k = -1;
    for (int i = 0; i < 4; i++)
        sim.step(idle, true);
    int n_files = 0;
    uint64_t n_golden = 0;
    if (!vecdir.empty())
        for (int i = 0; i < NK; i++) {
            std::vector<Sample> v = read_vectors(vecdir, i, &n_files);
            for (const Sample &s : v) {
                // the file's output is the C's: a stale golden file fails here
                if (kernels[i].fk->fx_fast(s.x) != s.file_out) {
                    if (sim.file_bad++ < 5)
                        printf("FAIL %s: golden vector output %016" PRIx64 " is not the C's\n", kernels[i].name,
                               s.file_out);
                }
                sim.step(s, false);
                n_golden++;
            }
        }
    for (uint64_t t = 0; t < n_random; t++) {
        Sample s;
        int focus = (int)((t >> 10) % (uint64_t)NK);
        for (int j = 0; j < NX; j++)
            s.x[j] = draw(j, focus);
        s.file_k = -1;
        bool second = t >= n_random / 2;
        uint64_t r = next_u64();
        s.valid = !second || (r & 7) != 0;
        bool rst = second && ((r >> 3) & 4095) == 0;
        sim.step(s, rst);
        if (rst) {
            int extra = (int)((r >> 16) % 3);
            for (int e = 0; e < extra; e++) {
                s.valid = (r >> (20 + e)) & 1;
                sim.step(s, true);
            }
        }
    }
    for (int i = 0; i < 64; i++)
        sim.step(idle, false);
    int passed = 0, failed = 0;
    for (int i = 0; i < NK; i++) {
        Kernel &k = kernels[i];
        uint64_t measured = k.first_out && k.first_in ? k.first_out - k.first_in + 1 : 0;
        bool ok = !k.bad && k.compared && measured == (uint64_t)k.lat;
        printf("%s %s: latency %" PRIu64 " (stated %d), %" PRIu64 " outputs compared (%" PRIu64
               " golden), %" PRIu64 " mismatches\n",
               ok ? "PASS" : "FAIL", k.name, measured, k.lat, k.compared * (uint64_t)k.outs, k.edges, k.bad);
        ok ? passed++ : failed++;
    }
    if (!vecdir.empty()) {
        bool ok = n_files > 0 && !sim.file_bad;
        printf("%s golden files: %d files, %" PRIu64 " vectors, outputs the C's\n", ok ? "PASS" : "FAIL", n_files,
               n_golden);
        ok ? passed++ : failed++;
    }
    printf("rtl_verilator: %d passed, %d failed, 0 skipped\n", passed, failed);
    top->final();
    delete top;
    return failed ? 1 : 0;
}
