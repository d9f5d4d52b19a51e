// fx_smith_vis_fit: the fitted visibility Vis = 1 / (nv R(nl) + nl R(nv)),
// R(x) = max(K1 a, K2 a + S3 x, K4 a + S5 x), S_i = K_i sigma(a), UQ16.16
// (facet_smith_vis_fit_fx_fast).  Mirrors the body's smith_vis_fit; a
// product by a Q15 value y is by_q15(v) = 2 hi(v, Y 2^16) (Q30 in, Q30 out):
//   c2a = by_q15(|C2|, a); sigma = 2^30 + by_q15(C1, a) - by_q15(c2a, a)
//   K_i a = by_q15(K_i, a); S3, S5 = hi(2 K_i, 2 sigma)
//   R(nl), R(nv): two by_q15 each, the two sums, the max of three (its
//     three compares side by side)
//   den45 = NV R(NL) + NL R(NV) in 64 bits, its top word dt (fx_top)
//   Vis 2^16 = 2^31 / dt 2^(e - 2): one fx_divb, b = 97 - e
module fx_smith_vis_fit (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                         input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_KA = 1 + L_MULHI, T_C2 = T_KA + L_MULHI, T_SG = T_C2 + 1, T_S = T_SG + L_MULHI;
    localparam T_B = T_S + L_MULHI, T_R = T_B + 2, T_M = T_R + L_MULW, T_TOP = T_M + 1 + L_TOP;
    localparam LATENCY = T_TOP + L_DIVB;
    reg [15:0] nl, nv, a;
    reg [31:0] sg, xl2, xl4, xv2, xv4, ka1e, rl, rv;
    reg [63:0] den;
    wire [31:0] c2a, c1a, ka1, ka2, ka4, c2aa, c1ad, s3, s5, bl3, bl5, bv3, bv5, ka1d, ka2d, ka4d;
    wire [15:0] a3, nlb, nvb, nlr, nvr;
    wire [63:0] ml, mv;
    wire [31:0] dt;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
        sg <= 32'd1073741824 + {c1ad[30:0], 1'b0} - {c2aa[30:0], 1'b0};                 // at T_SG
        xl2 <= ka2d + {bl3[30:0], 1'b0};                                                 // at T_B + 1
        xl4 <= ka4d + {bl5[30:0], 1'b0};
        xv2 <= ka2d + {bv3[30:0], 1'b0};
        xv4 <= ka4d + {bv5[30:0], 1'b0};
        ka1e <= ka1d;
        rl <= ka1e >= xl2 && ka1e >= xl4 ? ka1e : xl2 >= xl4 ? xl2 : xl4;               // at T_R
        rv <= ka1e >= xv2 && ka1e >= xv4 ? ka1e : xv2 >= xv4 ? xv2 : xv4;
        den <= ml + mv;                                                                  // at T_M + 1
    end
    fx_mulhi #(32, 16, 16) m1 (clk, K_VFIT_C2, {16'd0, a}, c2a);
    fx_mulhi #(32, 16, 16) m2 (clk, K_VFIT_C1, {16'd0, a}, c1a);
    fx_mulhi #(32, 16, 16) m3 (clk, K_VFIT_K1, {16'd0, a}, ka1);
    fx_mulhi #(32, 16, 16) m4 (clk, K_VFIT_K2, {16'd0, a}, ka2);
    fx_mulhi #(32, 16, 16) m5 (clk, K_VFIT_K4, {16'd0, a}, ka4);                      // at T_KA
    fx_delay #(16, T_KA - 1) da (clk, a, a3);
    fx_mulhi #(32, 16, 16) m6 (clk, {c2a[30:0], 1'b0}, {16'd0, a3}, c2aa);             // at T_C2
    fx_delay #(32, T_C2 - T_KA) dc1 (clk, c1a, c1ad);
    fx_mulhi #(32, 32, 1) m7 (clk, K_VFIT_K3 << 1, sg, s3);                            // at T_S
    fx_mulhi #(32, 32, 1) m8 (clk, K_VFIT_K5 << 1, sg, s5);
    fx_delay #(32, T_S - 1) dnl (clk, {nl, nv}, {nlb, nvb});
    fx_mulhi #(32, 16, 16) m9 (clk, s3, {16'd0, nlb}, bl3);                            // at T_B
    fx_mulhi #(32, 16, 16) m10 (clk, s5, {16'd0, nlb}, bl5);
    fx_mulhi #(32, 16, 16) m11 (clk, s3, {16'd0, nvb}, bv3);
    fx_mulhi #(32, 16, 16) m12 (clk, s5, {16'd0, nvb}, bv5);
    fx_delay #(96, T_B - T_KA) dka (clk, {ka1[30:0], 1'b0, ka2[30:0], 1'b0, ka4[30:0], 1'b0},
                                    {ka1d, ka2d, ka4d});
    fx_delay #(32, T_R - T_S) dnv (clk, {nlb, nvb}, {nlr, nvr});
    fx_mulw #(16, 32) m13 (clk, {16'd0, nvr}, rl, ml);                                  // at T_M
    fx_mulw #(16, 32) m14 (clk, {16'd0, nlr}, rv, mv);
    fx_top tp (clk, den, dt, e);                                                        // at T_TOP
    fx_divb #(K_MAX_VIS) dv (clk, 32'h80000000, dt, 32'd97 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
