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
    localparam T_DOTS = 1 + L_DOTS, T_SQ = T_DOTS + L_SQRT32, T_R = T_SQ + L_TAB20, T_X = T_R + L_MULHI;
    localparam LATENCY = T_X + 3;
    reg [15:0] nl, nv;
    reg [31:0] lov1;
    reg wz5, wz2;
    reg [31:0] xs, v2;
    wire wzd;
    wire [16:0] s, sd;
    wire [31:0] u, w, c, rs, r, x;
    wire [3:0] rh, rhd;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        lov1 <= lov;
        wz5 <= w == 32'd0;                                         // at T_DOTS + 1
    end
    fx_dots dots (clk, nl, nv, lov1, s, u, w, c);                  // at T_DOTS
    fx_sqrt32 sq (clk, c, rs, rh);                                 // at T_SQ
    fx_tab20 #(0) rcp (clk, rs << 12, r);                          // at T_R
    fx_delay #(17, T_R - T_DOTS) ds (clk, s, sd);
    fx_mulhi #(17, 20, 27) mx (clk, {15'd0, sd}, r, x);            // at T_X
    fx_delay #(4, T_X - T_SQ) dh (clk, rh, rhd);
    fx_delay #(1, T_X - T_DOTS) dw (clk, wz5, wzd);
    wire [31:0] xr = xs + 32'd1;
    always @(posedge clk) begin
        xs <= x >> (5'd14 - {1'b0, rhd});                          // round(x / 2^(15 - h)): the shift,
        v2 <= {1'b0, xr[31:1]};                                    // the rounding,
        wz2 <= wzd;
        y <= wz2 ? 32'd32768 : f_min(v2, 32'd32768);               // the saturation and N.H = 1
    end
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
