// fx_noh_from_dots: N.H from the dots, N.H = (n.l + n.v) / sqrt(2 + 2 l.v),
// Q15 (facet_noh_from_dots_fx_fast).  Mirrors the body's noh_from_dots:
//   1: the two-cosine clamps
//   the dot triple (fx_dots): s = NL + NV, w (0 at or past N.H = 1), c =
//     L.H^2 2^32 - 1
//   L.H = s_c 2^-(20 + h) (fx_sqrt32); r = rcp20(s_c 2^12) ~ 2^39 / s_c
//   x = hi(S 2^15, r 2^12); raw = round(x / 2^(15 - h)), at most 2^15;
//   w = 0 gives 2^15
module fx_noh_from_dots (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                         input [31:0] lov, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T4 = 1 + L_DOTS, T9 = T4 + L_SQRT32, T13 = T9 + L_TAB20, T15 = T13 + L_MULHI;
    localparam LATENCY = T15 + 1;
    reg [15:0] nl, nv;
    reg [31:0] lov1;
    reg wz5;
    wire [16:0] s, sd;
    wire [31:0] u, w, c, rs, r, x;
    wire [3:0] rh, rhd;
    wire wzd;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        lov1 <= lov;
        wz5 <= w == 32'd0;
    end
    fx_dots dots (clk, nl, nv, lov1, s, u, w, c);                  // at T4
    fx_sqrt32 sq (clk, c, rs, rh);                                 // at T9
    fx_tab20 #(0) rcp (clk, rs << 12, r);                          // at T13
    fx_delay #(17, T13 - T4) ds (clk, s, sd);
    fx_mulhi #(17, 20, 27) mx (clk, {15'd0, sd}, r, x);            // at T15
    fx_delay #(4, T15 - T9) dh (clk, rh, rhd);
    fx_delay #(1, T15 - T4 - 1) dw (clk, wz5, wzd);
    wire [31:0] xs = (x >> (5'd14 - {1'b0, rhd})) + 32'd1;
    always @(posedge clk) y <= wzd ? 32'd32768 : f_min({1'b0, xs[31:1]}, 32'd32768);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
