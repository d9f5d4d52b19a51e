// fx_smith_vis_hammon: Hammon's visibility Vis = 0.5 / m, UQ16.16
// (facet_smith_vis_hammon_fx_fast): fx_smith2, DEN 0, VIS 1.
module fx_smith_vis_hammon (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    fx_smith2 #(0, 1) k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
