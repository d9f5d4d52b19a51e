// fx_ggx_d: the GGX distribution D = a^2 / (pi d^2), d = (1 - n)(1 + n) +
// (n a)^2, UQ19.13 (facet_ggx_d_fx_fast).  Mirrors the body's ggx_d:
//   1: the unit and alpha clamps
//   2: NA = N A, W = (2^15 - N)(2^15 + N), A^2 (16-bit products)
//   d60 = W 2^30 + (NA)^2 exact in 64 bits [2^40 .. 2^60]; its top word dt
//   (fx_top: d = dt 2^-(28 + e)); pd = hi(hi(dt, dt), pi 2^30)
//   D 2^13 = A^2 / pd 2^(5 + 2e): one fx_divb, b = 90 - 2e, saturated
module fx_ggx_d (input clk, input rst, input in_valid, input [31:0] noh, input [31:0] alpha,
                 output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_MUL = 1 + L_MUL, T_SQ = T_MUL + L_MULW, T_TOP = T_SQ + 1 + L_TOP, T_PD = T_TOP + 2 * L_MULHI;
    localparam LATENCY = T_PD + L_DIVB;
    reg [15:0] n, a, omn;
    reg [16:0] opn;
    reg [63:0] d60;
    reg [31:0] b7;
    wire [31:0] na, w1, aa, w1d, dt, t2, pd, aad, b10;
    wire [63:0] nn;
    wire [5:0] e;
    always @(posedge clk) begin
        n <= f_unit(noh);
        a <= f_alpha(alpha);
        omn <= 32'd32768 - f_unit(noh);
        opn <= 32'd32768 + f_unit(noh);
        d60 <= nn + {2'd0, w1d, 30'd0};
        b7 <= 32'd90 - {e, 1'b0};
    end
    fx_mul #(16, 16) m1 (clk, {16'd0, n}, {16'd0, a}, na);
    fx_mul #(16, 17) m2 (clk, {16'd0, omn}, {15'd0, opn}, w1);
    fx_mul #(16, 16) m3 (clk, {16'd0, a}, {16'd0, a}, aa);
    fx_mulw #(31, 31) m4 (clk, na, na, nn);
    fx_delay #(32, L_MULW) d1 (clk, w1, w1d);
    fx_top tp (clk, d60, dt, e);                                   // at T_TOP
    fx_mulhi #(32, 32, 0) m5 (clk, dt, dt, t2);
    fx_mulhi #(32, 32, 0) m6 (clk, t2, K_PI_30, pd);               // at T_PD
    fx_delay #(32, T_PD - T_MUL) d2 (clk, aa, aad);
    fx_delay #(32, T_PD - T_TOP - 1) d3 (clk, b7, b10);
    fx_divb #(K_MAX_D) dv (clk, aad, pd, b10, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
