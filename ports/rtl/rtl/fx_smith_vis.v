// fx_smith_vis: Smith's height-correlated Vis = 0.5 / (nv r(nl) + nl r(nv)), UQ16.16
// (facet_smith_vis_fx_fast): fx_smith2, DEN 1, VIS 1.
module fx_smith_vis (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    fx_smith2 #(1, 1) k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
