// fx_smith_g2_uncorrelated: G1(nl) G1(nv) = 4 nl nv / ((nl + r(nl))(nv +
// r(nv))), Q15 (facet_smith_g2_uncorrelated_fx_fast): fx_smith_g2x, UNC 1.
module fx_smith_g2_uncorrelated (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
    input [31:0] alpha, output out_valid, output [31:0] y);
    fx_smith_g2x #(1) k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
