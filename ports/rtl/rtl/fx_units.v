// fx_units.v - the shared pipelined units the kernels are built from, each
// mirroring one piece of the fast tier's C body (src/fx/fx_fast_body.h) or
// of its op layer (src/fx/fx_ops_scalar.h).  Every unit has a fixed latency
// (fx_lat.vh), takes a new sample every clock, and has no reset: the data
// path free-runs and the kernel's valid bit (fx_valid) says which samples
// are real.  Verilog-2005.
//
// Operand widths: a product unit takes its operands' widths (AW, BW) from
// the bracketed bounds of the C body (e.g. a Q15 value <= 2^15 is 16 bits);
// a shifted operand (a << sa) is passed unshifted with the shift in SH, so
// hi(a << sa, b << sb) = (a b) >> (32 - sa - sb).  Simulation checks every
// width claim on every clock (FX_WIDTH_ERROR); synthesis sees the narrow
// multiplier.

// ---- delay line and valid --------------------------------------------------
module fx_delay #(parameter W = 32, parameter N = 1) (input clk, input [W-1:0] d, output [W-1:0] q);
    generate
        if (N == 0) begin : g_wire
            assign q = d;
        end else if (N == 1) begin : g_one
            reg [W-1:0] r;
            always @(posedge clk) r <= d;
            assign q = r;
        end else begin : g_line
            reg [W*N-1:0] r;
            always @(posedge clk) r <= {r[W*(N-1)-1:0], d};
            assign q = r[W*N-1 -: W];
        end
    endgenerate
endmodule

// the valid bit beside the data: N stages, cleared by the synchronous reset
module fx_valid #(parameter N = 1) (input clk, input rst, input d, output q);
    generate
        if (N == 1) begin : g_one
            reg r;
            always @(posedge clk) r <= rst ? 1'b0 : d;
            assign q = r;
        end else begin : g_line
            reg [N-1:0] r;
            always @(posedge clk) r <= rst ? {N{1'b0}} : {r[N-2:0], d};
            assign q = r[N-1];
        end
    endgenerate
endmodule

// simulation-only check that a value fits W bits (the width claims)
module fx_fits #(parameter W = 32) (input clk, input [63:0] v);
`ifndef SYNTHESIS
    always @(posedge clk)
        if (W < 64 && (v >> W) != 64'd0)
            $display("FX_WIDTH_ERROR %m: %h wider than %0d bits", v, W);
`endif
endmodule

// ---- products --------------------------------------------------------------
// a * b mod 2^32 of narrow operands (the op layer's 32-bit product): one
// 16x16 DSP block when both fit 16 bits
module fx_mul #(parameter AW = 16, parameter BW = 16) (input clk, input [31:0] a, input [31:0] b,
                                                       output reg [31:0] y);
    wire [AW+BW-1:0] p = a[AW-1:0] * b[BW-1:0];
    wire [63:0] p64 = {{(64-AW-BW){1'b0}}, p};
    always @(posedge clk) y <= p64[31:0];
    fx_fits #(AW) fa (clk, {32'd0, a});
    fx_fits #(BW) fb (clk, {32'd0, b});
endmodule

// the exact 64-bit product (the op layer's widening product), as 16x16
// partial products (one DSP block each) registered; the two middle ones
// summed; then the total, {hh, ll} + mid 2^16 (hh and ll do not overlap: one
// carry chain)
module fx_mulw #(parameter AW = 32, parameter BW = 32) (input clk, input [31:0] a, input [31:0] b,
                                                        output reg [63:0] y);
    localparam AL = AW > 16 ? 16 : AW, BL = BW > 16 ? 16 : BW;
    localparam AH = AW > 16 ? AW - 16 : 1, BH = BW > 16 ? BW - 16 : 1;
    reg [AL+BL-1:0] p_ll;
    wire [AH+BL-1:0] p_hl;
    wire [AL+BH-1:0] p_lh;
    wire [AH+BH-1:0] p_hh;
    reg [63:0] ends2;
    reg [33:0] mid2;
    always @(posedge clk) p_ll <= a[AL-1:0] * b[BL-1:0];
    generate
        if (AW > 16) begin : g_hl
            reg [AH+BL-1:0] r;
            always @(posedge clk) r <= a[AW-1:16] * b[BL-1:0];
            assign p_hl = r;
        end else begin : g_no_hl
            assign p_hl = 0;
        end
        if (BW > 16) begin : g_lh
            reg [AL+BH-1:0] r;
            always @(posedge clk) r <= a[AL-1:0] * b[BW-1:16];
            assign p_lh = r;
        end else begin : g_no_lh
            assign p_lh = 0;
        end
        if (AW > 16 && BW > 16) begin : g_hh
            reg [AH+BH-1:0] r;
            always @(posedge clk) r <= a[AW-1:16] * b[BW-1:16];
            assign p_hh = r;
        end else begin : g_no_hh
            assign p_hh = 0;
        end
    endgenerate
    always @(posedge clk) begin
        ends2 <= ({{(64-AH-BH){1'b0}}, p_hh} << 32) | {{(64-AL-BL){1'b0}}, p_ll};
        mid2 <= {{(34-AH-BL){1'b0}}, p_hl} + {{(34-AL-BH){1'b0}}, p_lh};
        y <= ends2 + ({30'd0, mid2} << 16);
    end
    fx_fits #(AW) fa (clk, {32'd0, a});
    fx_fits #(BW) fb (clk, {32'd0, b});
endmodule

// the high word of a 32x32 product, floor((a 2^sa)(b 2^sb) / 2^32) with
// SH = sa + sb (the body's fxw_mulhi; the C keeps both shifted operands
// below 2^32, so the shifts lose nothing)
module fx_mulhi #(parameter AW = 32, parameter BW = 32, parameter SH = 0) (input clk, input [31:0] a,
                                                                           input [31:0] b, output [31:0] y);
    wire [63:0] p;
    fx_mulw #(AW, BW) m (clk, a, b, p);
    assign y = p[32-SH +: 32];
    fx_fits #(64 - SH) fp (clk, p);
endmodule

// ---- tables ----------------------------------------------------------------
// 1/x and sqrt by the 129- and 97-entry Q20 tables, 7 index bits and 15
// bits of linear interpolation (the body's rcp20 and sqrt20):
//   SQRT = 0: r ~ 2^51 / m for m in [2^31, 2^32): index m[30:24] (= (m >> 24)
//             - 128), fraction m[23:9]; r = R[i] - (((R[i] - R[i+1]) f + 2^14) >> 15)
//   SQRT = 1: s ~ 2^20 sqrt(x / 2^32) for x in [2^30, 2^32): index x[31:25] -
//             32, fraction x[24:10]; s = S[j] + (((S[j+1] - S[j]) f + 2^14) >> 15)
// Stages: ROM read; the step (< 2^13, checked by the generator); the
// 13x15 product; the rounded correction; the interpolated value.
module fx_tab20 #(parameter SQRT = 0) (input clk, input [31:0] x, output reg [31:0] y);
    wire [39:0] q;
    reg [14:0] f1, f2;
    reg [19:0] t2, t3, t4;
    reg [12:0] d2;
    reg [27:0] p3;
    reg [12:0] c4;
    generate
        if (SQRT) begin : g_sqrt
            fx_rom_sqrt rom (clk, x[31:25] - 7'd32, q);
        end else begin : g_rcp
            fx_rom_rcp rom (clk, x[30:24], q);
        end
    endgenerate
    always @(posedge clk) begin
        f1 <= SQRT ? x[24:10] : x[23:9];
        f2 <= f1;
        t2 <= q[19:0];
        d2 <= SQRT ? q[39:20] - q[19:0] : q[19:0] - q[39:20];
        t3 <= t2;
        p3 <= d2 * f2;
        t4 <= t3;
        c4 <= (p3 + 28'd16384) >> 15;
        y <= SQRT ? {12'd0, t4} + {19'd0, c4} : {12'd0, t4} - {19'd0, c4};
    end
`ifndef SYNTHESIS
    always @(posedge clk)
        if (x != 32'd0 && (SQRT ? x[31:30] == 2'd0 : !x[31])) // 0: the empty pipeline
            $display("FX_WIDTH_ERROR %m: table input %h not normalised", x);
`endif
endmodule

// sqrt(c 2^-32) for c in [2^16 - 1, 2^32) (the body's sqrt32): the even
// normalising shift 2h (h <= 8), the sqrt table: sqrt = s 2^-(20 + h)
module fx_sqrt32 (input clk, input [31:0] c, output [31:0] s, output [3:0] h);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    wire [5:0] k = f_clz(c) & 6'd30;
    reg [31:0] cn;
    reg [3:0] h1;
    always @(posedge clk) begin
        cn <= c << k;
        h1 <= k[4:1];
    end
    fx_tab20 #(1) t (clk, cn, s);
    fx_delay #(4, L_TAB20) dh (clk, h1, h);
endmodule

// ---- normalisation ---------------------------------------------------------
// the top 32 bits of v, 2^26 <= v < 2^63 (the body's fxw_top): kk =
// min(clz(hi), 31) in [1, 31], top = (hi << kk) | (lo >> (32 - kk))
module fx_top (input clk, input [63:0] v, output reg [31:0] t, output reg [5:0] e);
    `include "fx_ops.vh"
    wire [5:0] kk = f_clz31(v[63:32]);
    always @(posedge clk) begin
        t <= (v[63:32] << kk) | (v[31:0] >> (6'd32 - kk));
        e <= kk;
    end
`ifndef SYNTHESIS
    always @(posedge clk)
        if (v[63] === 1'b1) $display("FX_WIDTH_ERROR %m: top of %h (>= 2^63)", v);
`endif
endmodule

// round(n / d 2^s) (ties up), saturated at MAX, s given biased as the lane
// b = 95 - s (the body's fxr_divb; n < 2^32, 0 gives 0; d >= 1):
//   1: kn = min(clz n, 31), kd = clz d; both normalised
//   r = rcp20(d 2^kd); q = hi(n 2^kn, r 2^12)
//   meanwhile sb = b + kn - kd, and for both kq = 0 and 1 the shift of the
//     rounding, sr = min(max(srb, 65) - 65, 31) of srb = sb + kq, and the
//     flags srb < 65, < 64, < 97 (the C forms srb after q; the same values)
//   Q1: kq = 1 - q[31], q 2^kq in [2^31, 2^32); its sr and flags selected
//   Q2: t = q >> sr;  Q3: the rounding (t + 1) / 2 for sr >= 0 (srb > 64),
//     saturation for sr < 0, 0 past 32;  Q4: min(v, MAX)
// NEWTON = 1 is the body's fxq_divbn (the G terms): the reciprocal refined
// by one Newton step (fxq_rcpn), r = rcp20 2^12, t = hi(dn, r), h = hi(r,
// ~t), q = hi(nn, 2h) (= (nn h) >> 31: SH 1): two more products
// (L_DIVBN = L_DIVB + 2 L_MULHI).
module fx_divb #(parameter [31:0] MAX = 32'hFFFFFFFF, parameter NEWTON = 0) (input clk, input [31:0] n,
                                                       input [31:0] d, input [31:0] b, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam TQ = 1 + L_TAB20 + (NEWTON ? 3 : 1) * L_MULHI; // q
    reg [31:0] nn1, dn1, b1, sb2, srb0, srb1, q1, t2, v3;
    reg [5:0] kn1, kd1;
    reg [4:0] sr0, sr1, sr;
    reg [2:0] fl0, fl1, fl, fl2;                      // {srb < 97, srb < 64, srb < 65}
    wire [31:0] rs, nnd, q;
    wire [4:0] sr0d, sr1d;
    wire [2:0] fl0d, fl1d;
    wire [31:0] t2p = t2 + 32'd1;                     // 32-bit: wraps as the C's add
    wire [31:0] e0 = srb0 - 32'd65, e1 = srb1 - 32'd65;
    always @(posedge clk) begin
        kn1 <= f_clz31(n);
        kd1 <= f_clz(d);
        nn1 <= n << f_clz31(n);
        dn1 <= d << f_clz(d);
        b1 <= b;
        sb2 <= b1 + kn1 - kd1;                        // 2
        srb0 <= sb2;                                  // 3
        srb1 <= sb2 + 32'd1;
        // 4: the shift min(max(srb, 65) - 65, 31), 0 below 65 (exact: a
        // difference past 31 has a bit set above bit 4)
        sr0 <= srb0 < 32'd65 ? 5'd0 : |e0[31:5] ? 5'd31 : e0[4:0];
        sr1 <= srb1 < 32'd65 ? 5'd0 : |e1[31:5] ? 5'd31 : e1[4:0];
        fl0 <= {srb0 < 32'd97, srb0 < 32'd64, srb0 < 32'd65};
        fl1 <= {srb1 < 32'd97, srb1 < 32'd64, srb1 < 32'd65};
        // Q1 .. Q4
        q1 <= q << !q[31];
        sr <= q[31] ? sr0d : sr1d;
        fl <= q[31] ? fl0d : fl1d;
        t2 <= q1 >> sr;
        fl2 <= fl;
        v3 <= fl2[1] ? MAX : !fl2[2] ? 32'd0 : fl2[0] ? t2 : {1'b0, t2p[31:1]};
        y <= f_min(v3, MAX);
    end
    fx_tab20 #(0) rcp (clk, dn1, rs);
    fx_delay #(32, TQ - L_MULHI - 1) dn (clk, nn1, nnd);
    generate
        if (NEWTON) begin : g_newton
            wire [31:0] dnd, t, rsd, h;
            fx_delay #(32, L_TAB20) dd (clk, dn1, dnd);
            fx_mulhi #(32, 20, 12) mt (clk, dnd, rs, t);          // t = hi(d, r) ~ 2^31
            fx_delay #(20, L_MULHI) dr (clk, rs[19:0], rsd[19:0]);
            assign rsd[31:20] = 12'd0;
            fx_mulhi #(20, 32, 12) mh (clk, rsd, ~t, h);         // h = hi(r, ~t) < 2^31
            // h < 2^31 for every d >= 1 (32 bits: an empty pipeline feeds d = 0)
            fx_mulhi #(32, 32, 1) mq (clk, nnd, h, q);           // at TQ
        end else begin : g_table
            fx_mulhi #(32, 20, 12) mq (clk, nnd, rs, q);         // at TQ
        end
    endgenerate
    fx_delay #(5, TQ - 4) ds0 (clk, sr0, sr0d);
    fx_delay #(5, TQ - 4) ds1 (clk, sr1, sr1d);
    fx_delay #(3, TQ - 4) df0 (clk, fl0, fl0d);
    fx_delay #(3, TQ - 4) df1 (clk, fl1, fl1d);
endmodule

// ---- the pieces several kernels share ---------------------------------------
// The dot triple (the body's dots_of): with S = NL + NV and t = L.V
// clamped to [-32767, 32768], offset: P = (2^16 - S)(2^16 + S), Q = (2^15 -
// LOV) 2^16, u = min(P, Q) (the facet.h raise, exact), w = P - u, c = ~u =
// L.H^2 2^32 - 1.  nl, nv clamped (16 bits), lov raw; s is 17 bits.
module fx_dots (input clk, input [15:0] nl, input [15:0] nv, input [31:0] lov, output [16:0] s,
                output reg [31:0] u, output reg [31:0] w, output reg [31:0] c);
    `include "fx_ops.vh"
    reg [16:0] s1, s2;
    reg [15:0] sm1;
    reg [17:0] sp1;
    reg [31:0] q1, q2;
    wire [31:0] p2;
    wire [31:0] t = f_clamp_off(lov, -32767, 32768);
    always @(posedge clk) begin
        s1 <= nl + nv;
        sm1 <= 17'd65536 - (nl + nv);
        sp1 <= 18'd65536 + (nl + nv);
        q1 <= (32'd65535 - t) << 16;
        s2 <= s1;
        q2 <= q1;
        u <= f_min(p2, q2);
        w <= p2 < q2 ? 32'd0 : p2 - q2;        // P - min(P, Q), the compare beside the subtract
        c <= ~f_min(p2, q2);
    end
    fx_mul #(16, 18) mp (clk, {16'd0, sm1}, {14'd0, sp1}, p2);
    fx_delay #(17, 1) ds (clk, s2, s);
endmodule

// x (1 + y + y^2 + y^3 + y^4) = 1 - (1 - x)^5, y = 1 - x, for X in [0, 2^15]
// (the body's p5): the 258-entry Q16 table at i = X >> 7, interpolated by
// the 7 bits below [steps < 2^12], times X: Q31 [< 2^31 + 2^15]
module fx_p5 (input clk, input [15:0] x, output [31:0] p);
    `include "fx_lat.vh"
    wire [37:0] q;
    reg [6:0] f1, f2;
    reg [15:0] x1, x2, x3, x4;
    reg [18:0] t2, t3;
    reg [11:0] d2;
    reg [18:0] p3;
    reg [18:0] s4;
    fx_rom_p5 rom (clk, x[15:7], q);
    always @(posedge clk) begin
        f1 <= x[6:0];
        x1 <= x;
        f2 <= f1;
        x2 <= x1;
        t2 <= q[18:0];
        d2 <= q[18:0] - q[37:19];
        t3 <= t2;
        x3 <= x2;
        p3 <= d2 * f2;
        s4 <= t3 - ((p3 + 19'd64) >> 7);
        x4 <= x3;
    end
    fx_mul #(16, 19) m (clk, {16'd0, x4}, {13'd0, s4}, p);
endmodule

// y^5 Q30 for Y = 2^15 y in [0, 2^15] (the body's y5 of Schlick's
// Fresnel): y2 = 2 Y^2 Q31, y4 = hi(y2, y2) Q30, y5 = hi(2 y4, Y 2^16) Q30
module fx_y5 (input clk, input [15:0] y, output [31:0] y5);
    `include "fx_lat.vh"
    wire [31:0] yy, y4;
    wire [15:0] yd;
    fx_mul #(16, 16) m2 (clk, {16'd0, y}, {16'd0, y}, yy);           // Y^2 <= 2^30
    fx_mulhi #(31, 31, 2) m4 (clk, yy, yy, y4);                      // hi(2 Y^2, 2 Y^2)
    fx_delay #(16, L_MUL + L_MULHI) dy (clk, y, yd);
    fx_mulhi #(31, 16, 17) m5 (clk, y4, {16'd0, yd}, y5);            // hi(2 y4, Y 2^16)
endmodule

// Hammon's rough term a rough Q25 (the body's diffuse26_rough), from
// a (16 bits), s = NL + NV, c = L.H^2 2^32 - 1 at time T; L.H = ls
// 2^-(20 + h) at T + L_SQRT32; x = c 2^k, k = 2h at T + L_SQRT32 + 1:
//   t45 = (4.5 - t) Q29 = 9 2^28 - c / 4;  mh = hi(x, t45)
//   1/s = rs 2^(ks - 36), rs = rcp20(s 2^ks);  q = 2^24 + hi(ls 2^12, rs 2^12) >> (h + 24 - ks)
//   x1 = hi(mh, A floor(2^20/10));  a rough = (hi(2 x1, q) 2) >> k
module fx_rough (input clk, input [15:0] a, input [16:0] s, input [31:0] c, input [19:0] ls, input [3:0] h,
                 input [31:0] x, input [4:0] k, output reg [31:0] rough);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam TLH = L_SQRT32, TX = L_SQRT32 + 1;           // input times after T
    localparam TQH = TLH + L_MULHI, TMH = TX + L_MULHI;     // products
    localparam TQ = TMH, TX1 = TQ + L_MULHI, TX2 = TX1 + L_MULHI;
    reg [31:0] t45, ss1, q8;
    reg [4:0] ks1;
    wire [31:0] rs0, rs, qh, mh, at, at8, x1, x2, t45x, q10;
    wire [4:0] ksq, kd;
    wire [3:0] hq;
    always @(posedge clk) begin
        t45 <= (32'd9 << 28) - (c >> 2);
        ks1 <= f_clz(s);
        ss1 <= {15'd0, s} << f_clz(s);
    end
    fx_tab20 #(0) rcp (clk, ss1, rs0);                                 // at T + 1 + L_TAB20
    fx_delay #(32, TLH - 1 - L_TAB20) drs (clk, rs0, rs);
    fx_mulhi #(20, 20, 24) mq (clk, {12'd0, ls}, rs, qh);              // at TQH
    fx_delay #(32, TX - 1) dt (clk, t45, t45x);
    fx_mulhi #(32, 32, 0) mm (clk, x, t45x, mh);                       // at TMH
    fx_delay #(5, TQ - 2) dks (clk, ks1, ksq);
    fx_delay #(4, TQ - 1 - TLH) dh (clk, h, hq);
    // q at TQ: TQH < TQ, so the product waits one clock in a register
    wire [31:0] qhd;
    fx_delay #(32, TQ - 1 - TQH) dqh (clk, qh, qhd);
    wire [5:0] qsh = {2'd0, hq} + 6'd24 - {1'b0, ksq};               // [1, 17]
    always @(posedge clk) q8 <= 32'd16777216 + (qhd >> qsh);
    fx_mul #(16, 17) ma (clk, {16'd0, a}, K_TENTH, at);
    fx_delay #(32, TMH - L_MUL) dat (clk, at, at8);
    fx_mulhi #(32, 32, 0) m1 (clk, mh, at8, x1);                       // at TX1
    fx_delay #(32, TX1 - TQ) dq (clk, q8, q10);
    fx_mulhi #(31, 32, 1) m2 (clk, x1, q10, x2);                       // at TX2
    fx_delay #(5, TX2 - TX) dk (clk, k, kd);
    always @(posedge clk) rough <= {x2[30:0], 1'b0} >> kd;             // at TX2 + 1 = L_ROUGH
endmodule

// The diffuse shape (the body's diffuse26_shape): a smooth term Q29,
// rounded to Q25, plus the rough term (fx_rough).  nl, nv, a, s, c at T; ls,
// h at T + L_SQRT32; x, k one later; the shape Q25 at T + L_SHAPE.  The
// smooth term by VARIANT (the three Hammon diffuse kernels):
//   0 diffuse_hammon: (1 - a) 1.05 P(nl) P(nv), P by fx_p5: hi(hi(Pl, Pv), 2 k1)
//   1 diffuse_hammon_hybrid: (1 - yl^5 / 2)(1 - yv^5 / 2)(1 - a):
//     fl = 2^30 - y5(1 - nl) / 2 Q30, hi(hi(2 fl, 2 fv), (2^15 - A) 2^16)
//   2 diffuse_hammon_cheap: (1 - a) Q29 exact
module fx_shape #(parameter VARIANT = 0) (input clk, input [15:0] nl, input [15:0] nv, input [15:0] a,
                                          input [16:0] s, input [31:0] c, input [19:0] ls, input [3:0] h,
                                          input [31:0] x, input [4:0] k, output reg [31:0] shape);
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam TS = VARIANT == 0 ? L_P5 + 2 * L_MULHI + 1 : VARIANT == 1 ? L_Y5 + 1 + 2 * L_MULHI + 1 : 1;
    wire [31:0] sm4, sm4d, rough;
    generate
        if (VARIANT == 0) begin : g_p5
            wire [31:0] pl, pv, pp, k1, k1d, sm;
            reg [31:0] r4;
            fx_p5 p5l (clk, nl, pl);
            fx_p5 p5v (clk, nv, pv);
            fx_mulhi #(32, 32, 0) mpp (clk, pl, pv, pp);                   // Q30
            fx_mul #(16, 16) mk (clk, 32'd32768 - a, K_C105, k1);          // (1 - a) 1.05 Q30
            fx_delay #(32, L_P5 + L_MULHI - L_MUL) dk1 (clk, k1, k1d);
            fx_mulhi #(32, 31, 1) msm (clk, pp, k1d, sm);                  // Q29
            always @(posedge clk) r4 <= (sm + 32'd8) >> 4;
            assign sm4 = r4;
        end else if (VARIANT == 1) begin : g_hybrid
            wire [31:0] y5l, y5v, m1, sm;
            wire [15:0] omad;
            reg [31:0] fl, fv, r4;
            reg [15:0] oma;
            fx_y5 ul (clk, 16'd32768 - nl, y5l);
            fx_y5 uv (clk, 16'd32768 - nv, y5v);
            always @(posedge clk) begin
                fl <= 32'd1073741824 - (y5l >> 1);
                fv <= 32'd1073741824 - (y5v >> 1);
                oma <= 32'd32768 - a;
                r4 <= (sm + 32'd8) >> 4;
            end
            fx_mulhi #(31, 31, 2) m1u (clk, fl, fv, m1);
            fx_delay #(16, L_Y5 + L_MULHI) da (clk, oma, omad);
            fx_mulhi #(31, 16, 16) m2u (clk, m1, {16'd0, omad}, sm);       // Q29
            assign sm4 = r4;
        end else begin : g_cheap
            reg [31:0] r4;
            always @(posedge clk) r4 <= (((32'd32768 - a) << 14) + 32'd8) >> 4;
            assign sm4 = r4;
        end
    endgenerate
    fx_delay #(32, L_ROUGH - TS) dsm (clk, sm4, sm4d);
    fx_rough r (clk, a, s, c, ls, h, x, k, rough);
    always @(posedge clk) shape <= sm4d + rough;
endmodule

// The albedo part (the body's diffuse26_albedo): the multi-scatter term
// albedo a 0.1159 pi Q31 rounded to Q25, added to the shape, times albedo
// / pi Q33: Q26.  a, alb at T; the shape at T + D_ALBEDO_SHAPE; out at
// T + L_ALBEDO.
module fx_albedo (input clk, input [15:0] a, input [15:0] alb, input [31:0] shape, output [31:0] d);
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    wire [31:0] ma, multi, ai, aid;
    reg [31:0] mr, b;
    fx_mul #(16, 16) m1 (clk, {16'd0, alb}, {16'd0, a}, ma);
    fx_mulhi #(31, 32, 1) m2 (clk, ma, K_MULTI, multi);                // Q31
    always @(posedge clk) begin
        mr <= (multi + 32'd32) >> 6;                                   // at D_ALBEDO_SHAPE
        b <= shape + mr;
    end
    fx_mul #(16, 17) m3 (clk, {16'd0, alb}, K_INV_PI, ai);            // albedo / pi Q33
    fx_delay #(32, D_ALBEDO_SHAPE + 1 - L_MUL) dai (clk, ai, aid);
    fx_mulhi #(32, 32, 0) m4 (clk, b, aid, d);
endmodule
