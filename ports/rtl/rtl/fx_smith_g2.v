// fx_smith_g2: Smith's height-correlated G2 = 2 nl nv / (nv r(nl) + nl r(nv)), Q15
// (facet_smith_g2_fx_fast): fx_smith_g2x, UNC 0.
module fx_smith_g2 (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    fx_smith_g2x #(0) k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
