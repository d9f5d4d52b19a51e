// fx_diffuse_hammon_hybrid: Hammon's rough and multi-scatter terms with the hybrid smooth term
// (facet_diffuse_hammon_hybrid_fx_fast), UQ8.24: fx_hammon_diffuse, VARIANT 1.
module fx_diffuse_hammon_hybrid (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] lov,
    input [31:0] alpha, input [31:0] albedo, output out_valid, output [31:0] y);
    fx_hammon_diffuse #(1) k (clk, rst, in_valid, nol, nov, lov, alpha, albedo, out_valid, y);
endmodule
