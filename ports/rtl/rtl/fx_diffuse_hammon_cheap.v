// fx_diffuse_hammon_cheap: Hammon's rough and multi-scatter terms with the smooth term (1 - a)
// (facet_diffuse_hammon_cheap_fx_fast), UQ8.24: fx_hammon_diffuse, VARIANT 2.
module fx_diffuse_hammon_cheap (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] lov,
    input [31:0] alpha, input [31:0] albedo, output out_valid, output [31:0] y);
    fx_hammon_diffuse #(2) k (clk, rst, in_valid, nol, nov, lov, alpha, albedo, out_valid, y);
endmodule
