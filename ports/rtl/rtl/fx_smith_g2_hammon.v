// fx_smith_g2_hammon: Hammon's G2 = 2 nl nv / m, m = (1 - a) 2 nl nv + a (nl + nv), Q15
// (facet_smith_g2_hammon_fx_fast): fx_smith2, DEN 0, VIS 0.
module fx_smith_g2_hammon (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    fx_smith2 #(0, 0) k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
