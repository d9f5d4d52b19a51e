// fx_smith_vis_hammon: Hammon's visibility Vis = 0.5 / m (fx_hammon_m),
// UQ16.16 (facet_smith_vis_hammon_fx_fast).  Mirrors the body's
// smith_vis_hammon: Vis 2^16 = 2^31 / mt 2^(e - 3), one fx_divb, b = 98 - e.
module fx_smith_vis_hammon (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                            input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam LATENCY = 1 + L_MUL + L_HAMMON_M + L_DIVB;
    reg [15:0] nl, nv, a;
    wire [15:0] nld, nvd, ad;
    wire [31:0] p, mt;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
    end
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(48, L_MUL) d (clk, {nl, nv, a}, {nld, nvd, ad});
    fx_hammon_m hm (clk, nld, nvd, ad, p, mt, e);
    fx_divb #(K_MAX_VIS) dv (clk, 32'h80000000, mt, 32'd98 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
