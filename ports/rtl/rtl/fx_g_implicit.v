// fx_g_implicit: the implicit G = N.L N.V, Q15 (facet_g_implicit_fx_fast):
// the unit clamps, the exact Q30 product, rounded once (the body's g_implicit).
module fx_g_implicit (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                      output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 1 + L_MUL + 1;
    reg [15:0] nl, nv;
    wire [31:0] p;
    always @(posedge clk) begin
        nl <= f_unit(nol);
        nv <= f_unit(nov);
        y <= (p + 32'd16384) >> 15;
    end
    fx_mul #(16, 16) m (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
