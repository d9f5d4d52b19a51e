// fx_g_neumann: Neumann's G = min(N.L, N.V), Q15, exact
// (facet_g_neumann_fx_fast; the body's g_neumann): the unit clamps, the min.
module fx_g_neumann (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                     output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    localparam LATENCY = 2;
    reg [15:0] nl, nv;
    always @(posedge clk) begin
        nl <= f_unit(nol);
        nv <= f_unit(nov);
        y <= f_min({16'd0, nl}, {16'd0, nv});
    end
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
