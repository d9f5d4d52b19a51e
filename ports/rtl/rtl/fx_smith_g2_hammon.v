// fx_smith_g2_hammon: Hammon's G2 = 2 nl nv / m (fx_hammon_m), Q15
// (facet_smith_g2_hammon_fx_fast).  Mirrors the body's smith_g2_hammon:
// G2 2^15 = NL NV / mt 2^(e - 1), one fx_divb, b = 96 - e, saturated at 1.
module fx_smith_g2_hammon (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                           input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 1 + L_MUL + L_HAMMON_M + L_DIVB;
    reg [15:0] nl, nv, a;
    wire [15:0] nld, nvd, ad;
    wire [31:0] p, pd, mt;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
    end
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(48, L_MUL) d (clk, {nl, nv, a}, {nld, nvd, ad});
    fx_hammon_m hm (clk, nld, nvd, ad, p, mt, e);
    fx_delay #(32, L_HAMMON_M) dp (clk, p, pd);
    fx_divb #(32768) dv (clk, pd, mt, 32'd96 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
