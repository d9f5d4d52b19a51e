// fx_smith_g1: Smith's G1 for GGX, 2 n / (n + r(n)), Q15
// (facet_smith_g1_fx_fast).  Mirrors the body's smith_g1: den30 = N 2^15 +
// r30 (fx_smith_r30) [<= 2^31]; G1 2^15 = 2N 2^30 / den30, one fx_divb (s =
// 30: b = 65), saturated at 1.
module fx_smith_g1 (input clk, input rst, input in_valid, input [31:0] nov, input [31:0] alpha,
                    output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T_R = 1 + L_MUL + L_R30, LATENCY = T_R + 1 + L_DIVB;
    reg [15:0] n, a;
    reg [31:0] den;
    wire [31:0] a2, r;
    wire [15:0] n2, nr;
    always @(posedge clk) begin
        n <= f_unit(nov);
        a <= f_alpha(alpha);
        den <= {1'b0, nr, 15'd0} + r;
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_delay #(16, L_MUL) dn (clk, n, n2);
    fx_smith_r30 sr (clk, n2, a2, r);                                       // at T_R
    fx_delay #(16, L_R30) dr (clk, n2, nr);
    wire [15:0] nd;
    fx_delay #(16, 1) dd (clk, nr, nd);
    fx_divb #(32768) dv (clk, {15'd0, nd, 1'b0}, den, 32'd65, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
