// fx_smith_vis: Smith's height-correlated Vis = 0.5 / den: Vis 2^16 = 2^31 / dt 2^(e - 3), b = 98 - e
// (facet_smith_vis_fx_fast; the body's smith_vis), UQ16.16: the
// denominator nv r(nl) + nl r(nv) and its top word by fx_smith_den, then
// one fx_divb.
module fx_smith_vis (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov, input [31:0] alpha,
    output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_D = 1 + L_MUL + L_SDEN, LATENCY = T_D + L_DIVB;
    reg [15:0] nl, nv, a;
    wire [31:0] a2, p, pd, dt;
    wire [15:0] nl2, nv2;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(32, L_MUL) dn (clk, {nl, nv}, {nl2, nv2});
    fx_smith_den sd (clk, nl2, nv2, a2, dt, e);                             // at T_D
    fx_delay #(32, L_SDEN) dp (clk, p, pd);
    fx_divb #(K_MAX_VIS) dv (clk, 32'h80000000, dt, 32'd98 - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
