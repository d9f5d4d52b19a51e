// fx_smith_g1: Smith's G1 for GGX, 2 n / (n + r(n)) = X / (X + Y), Q15
// (facet_smith_g1_fx_fast).  Mirrors the body's smith_g1: the tops xt, dt
// of X and X + Y (fx_smith_xd); G1 2^15 = round(2^15 (1 - (dt - xt) / dt))
// (fx_one_minus15: one fx_divb NEWTON).
module fx_smith_g1 (input clk, input rst, input in_valid, input [31:0] nov, input [31:0] alpha,
                    output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T_XD = 1 + L_MUL + L_XD, LATENCY = T_XD + 1 + L_OM15;
    reg [15:0] n, a;
    reg [31:0] q, d;
    wire [31:0] a2, xt, dt;
    wire [15:0] n2;
    always @(posedge clk) begin
        n <= f_unit(nov);
        a <= f_alpha(alpha);
        q <= dt - xt;                                                    // T_XD + 1
        d <= dt;
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_delay #(16, L_MUL) dn (clk, n, n2);
    fx_smith_xd sx (clk, n2, a2, xt, dt);                                   // at T_XD
    fx_one_minus15 om (clk, q, d, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
