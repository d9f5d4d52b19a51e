// fx_smith2: the two-cosine Smith terms that divide by one denominator (the
// body's smith_g2 / smith_vis over g2_den, and smith_g2_hammon /
// smith_vis_hammon over hammon_m): the clamps, NL NV and A^2, the
// denominator's top word dt ~ 2^(32 - e), then one fx_divb:
//   VIS = 0: G2 2^15 = NL NV / dt 2^(e - 1)   (b = 96 - e), Q15, saturated at 1
//   VIS = 1: Vis 2^16 = 2^31 / dt 2^(e - 3)   (b = 98 - e), UQ16.16
//   DEN = 0: Hammon's m45 (fx_hammon_m);  DEN = 1: nv r(nl) + nl r(nv) (fx_smith_den)
// A G term (VIS = 0) divides by fx_divb NEWTON (the body's fxq_divbn: monotone);
// smith_g2 itself is fx_smith_g2x (its monotone form), so DEN = 1 is Vis only.
module fx_smith2 #(parameter DEN = 0, parameter VIS = 0) (input clk, input rst, input in_valid, input [31:0] nol,
    input [31:0] nov, input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam L_DEN = DEN ? L_SDEN : L_HAMMON_M, T_D = 1 + L_MUL + L_DEN, LATENCY = T_D + (VIS ? L_DIVB : L_DIVBN);
    reg [15:0] nl, nv, a;
    wire [31:0] a2, p, pd, dt;
    wire [15:0] nl2, nv2, a1;
    wire [5:0] e;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
    end
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_delay #(48, L_MUL) dn (clk, {nl, nv, a}, {nl2, nv2, a1});
    generate
        if (DEN) begin : g_smith
            fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
            fx_smith_den sd (clk, nl2, nv2, a2, dt, e);
        end else begin : g_hammon
            fx_hammon_m hm (clk, nl2, nv2, a1, p, dt, e);
        end
    endgenerate
    fx_delay #(32, L_DEN) dp (clk, p, pd);
    fx_divb #(VIS ? K_MAX_VIS : 32'd32768, VIS ? 0 : 1) dv (clk, VIS ? 32'h80000000 : pd, dt, (VIS ? 32'd98 : 32'd96) - e, y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
