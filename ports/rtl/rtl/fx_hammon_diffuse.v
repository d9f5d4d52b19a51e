// fx_hammon_diffuse: Hammon's diffuse, UQ8.24, the three smooth terms by
// VARIANT (fx_shape): 0 facet_diffuse_hammon_fx_fast, 1 ..._hybrid, 2
// ..._cheap.  Mirrors the body's diffuse_hammon (and hammon_variant):
//   1: the two-cosine, alpha and unit clamps
//   the dot triple (fx_dots): s, c = L.H^2 2^32 - 1 (the raised t)
//   L.H = ls 2^-(20 + h) (fx_sqrt32); x = c 2^k, k = 2h
//   the shape Q25 (fx_shape: smooth + rough), the albedo part Q26 (fx_albedo)
//   raw = (2 d + 5) / 8: (d + 2.5) / 4, half the mean floor added
module fx_hammon_diffuse #(parameter VARIANT = 0) (input clk, input rst, input in_valid, input [31:0] nol,
                                                   input [31:0] nov, input [31:0] lov, input [31:0] alpha,
                                                   input [31:0] albedo, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T4 = 1 + L_DOTS, T9 = T4 + L_SQRT32, T18 = T4 + L_SHAPE, TA = T18 - D_ALBEDO_SHAPE;
    localparam LATENCY = TA + L_ALBEDO + 1;
    reg [15:0] nl, nv, a, alb;
    reg [31:0] lov1, x;
    reg [4:0] k;
    wire [16:0] s;
    wire [31:0] u, w, c, c9, ls, shape, d;
    wire [3:0] h;
    wire [15:0] nl4, nv4, a4, aa, alba;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
        alb <= f_unit(albedo);
        lov1 <= lov;
        k <= {h, 1'b0};                                           // at T9 + 1
        x <= c9 << {h, 1'b0};
        y <= ({d[30:0], 1'b0} + 32'd5) >> 3;
    end
    fx_dots dots (clk, nl, nv, lov1, s, u, w, c);                 // at T4
    fx_sqrt32 sq (clk, c, ls, h);                                 // at T9
    fx_delay #(32, L_SQRT32) dc (clk, c, c9);
    fx_delay #(48, L_DOTS) d4 (clk, {nl, nv, a}, {nl4, nv4, a4});
    fx_shape #(VARIANT) sh (clk, nl4, nv4, a4, s, c, ls[19:0], h, x, k, shape);   // at T18
    fx_delay #(32, TA - 1) da (clk, {a, alb}, {aa, alba});
    fx_albedo al (clk, aa, alba, shape, d);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
