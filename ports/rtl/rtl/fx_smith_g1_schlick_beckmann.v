// fx_smith_g1_schlick_beckmann: Schlick's Beckmann G1 = n / (n (1 - k) + k),
// k = a sqrt(2/pi), Q15 (facet_smith_g1_schlick_beckmann_fx_fast).  Mirrors
// the body's smith_g1_schlick_beckmann:
//   k Q31 = hi(A 2^16, sqrt(2/pi) 2^32)
//   den46 = N (2^31 - k) + k 2^15 exact in 64 bits; its top word dt (fx_top)
//   G1 2^15 = N / dt 2^(14 + e): one fx_divb NEWTON (the refined reciprocal:
//   monotone), b = 81 - e, saturated at 1
module fx_smith_g1_schlick_beckmann (input clk, input rst, input in_valid, input [31:0] nov,
                                     input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_K = 1 + L_MULHI, T_OMK = T_K + 1, T_MW = T_OMK + L_MULW, T_TOP = T_MW + 1 + L_TOP;
    localparam LATENCY = T_TOP + L_DIVBN;
    reg [15:0] n, a;
    reg [31:0] omk, k4;
    reg [63:0] den;
    wire [31:0] k, kd, dt;
    wire [15:0] n4, n8;
    wire [63:0] mw;
    wire [5:0] e;
    always @(posedge clk) begin
        n <= f_unit(nov);
        a <= f_alpha(alpha);
        omk <= 32'h80000000 - k;
        k4 <= k;
        den <= mw + {17'd0, kd, 15'd0};
    end
    fx_mulhi #(16, 32, 16) mk (clk, {16'd0, a}, K_SQRT_2_PI, k);      // at T_K
    fx_delay #(16, T_OMK - 1) dn (clk, n, n4);
    fx_mulw #(16, 32) mw1 (clk, {16'd0, n4}, omk, mw);                // at T_MW
    fx_delay #(32, L_MULW) dk (clk, k4, kd);
    fx_top tp (clk, den, dt, e);                                      // at T_TOP
    fx_delay #(16, T_TOP - T_OMK) dn2 (clk, n4, n8);
    fx_divb #(32768, 1) dv (clk, {16'd0, n8}, dt, 32'd81 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
