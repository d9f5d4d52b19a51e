// fx_smith_g2_uncorrelated: G1(nl) G1(nv) = 4 nl nv / ((nl + r(nl))(nv +
// r(nv))), Q15 (facet_smith_g2_uncorrelated_fx_fast).  Mirrors the body's
// smith_g2_uncorrelated: the two sums Q30 (fx_smith_r30) [<= 2^31], their
// product Q60 and its top word pt (fx_top); G 2^15 = NL NV / pt 2^(15 + e),
// one fx_divb, b = 80 - e, saturated at 1.
module fx_smith_g2_uncorrelated (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
    input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T_R = 1 + L_MUL + L_R30, T_T = T_R + 1 + L_MULW + L_TOP, LATENCY = T_T + L_DIVB;
    reg [15:0] nl, nv, a;
    reg [31:0] dl, dv;
    wire [31:0] a2, p, pd, rl, rv, pt;
    wire [15:0] nl2, nv2, nlr, nvr;
    wire [63:0] pp;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
        dl <= {1'b0, nlr, 15'd0} + rl;                                      // T_R + 1
        dv <= {1'b0, nvr, 15'd0} + rv;
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(32, L_MUL) dn (clk, {nl, nv}, {nl2, nv2});
    fx_smith_r30 sl (clk, nl2, a2, rl);                                     // at T_R
    fx_smith_r30 sv (clk, nv2, a2, rv);
    fx_delay #(32, L_R30) dr (clk, {nl2, nv2}, {nlr, nvr});
    fx_mulw #(32, 32) mw (clk, dl, dv, pp);
    fx_top tp (clk, pp, pt, e);                                             // at T_T
    fx_delay #(32, T_T - (1 + L_MUL)) dp (clk, p, pd);
    fx_divb #(32768) dvb (clk, pd, pt, 32'd80 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
