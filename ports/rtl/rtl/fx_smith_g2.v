// fx_smith_g2: Smith's height-correlated G2 = 2 nl nv / den: G2 2^15 = NL NV / dt 2^(e - 1), b = 96 - e, saturated at 1
// (facet_smith_g2_fx_fast; the body's smith_g2), Q15: the
// denominator nv r(nl) + nl r(nv) and its top word by fx_smith_den, then
// one fx_divb.
module fx_smith_g2 (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_D = 1 + L_MUL + L_SDEN, LATENCY = T_D + L_DIVB;
    reg [15:0] nl, nv, a;
    wire [31:0] a2, p, pd, dt;
    wire [15:0] nl2, nv2;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(32, L_MUL) dn (clk, {nl, nv}, {nl2, nv2});
    fx_smith_den sd (clk, nl2, nv2, a2, dt, e);                             // at T_D
    fx_delay #(32, L_SDEN) dp (clk, p, pd);
    fx_divb #(32768) dv (clk, pd, dt, 32'd96 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
