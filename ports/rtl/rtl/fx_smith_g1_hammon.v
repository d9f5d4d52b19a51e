// fx_smith_g1_hammon: Hammon's G1 ~ 2 n / (n (2 - a) + a), Q15
// (facet_smith_g1_hammon_fx_fast).  Mirrors the body's smith_g1_hammon:
// den30 = N (2^16 - A) + A 2^15 exact [2^20 .. 2^31]; G1 2^15 = 2N 2^30 /
// den30, one fx_divb NEWTON (s = 30: b = 65; the refined reciprocal: monotone),
// saturated at 1.
module fx_smith_g1_hammon (input clk, input rst, input in_valid, input [31:0] nov, input [31:0] alpha,
                           output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 1 + L_MUL + 1 + L_DIVBN;
    reg [15:0] n, a, a2;
    reg [16:0] om, n2, n3;
    reg [31:0] den;
    wire [31:0] nm;
    always @(posedge clk) begin
        n <= f_unit(nov);
        a <= f_alpha(alpha);
        om <= 32'd65536 - f_alpha(alpha);
        a2 <= a;
        n2 <= {n, 1'b0};
        n3 <= n2;
        den <= nm + {1'b0, a2, 15'd0};
    end
    fx_mul #(16, 17) m (clk, {16'd0, n}, {15'd0, om}, nm);
    fx_divb #(32768, 1) dv (clk, {15'd0, n3}, den, 32'd65, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
