// fx_smith_g2x: the two GGX G2 terms in their monotone form (the body's
// smith_g2 and smith_g2_uncorrelated), from each cosine's tops x, d of X =
// 2n (n + r) and X + Y (fx_smith_xd; x / d = G1 of that cosine), y = d - x:
//   UNC = 0: G2 = x_l x_v / (d_l d_v - y_l y_v)   (1 / (1/g_l + 1/g_v - 1))
//   UNC = 1: G1 G1 = x_l x_v / (d_l d_v)
// the denominator D and D - x_l x_v in 64 bits, their high words, then
// round(2^15 (1 - (D - x_l x_v) / D)) (fx_one_minus15).  Q15.
module fx_smith_g2x #(parameter UNC = 0) (input clk, input rst, input in_valid, input [31:0] nol,
    input [31:0] nov, input [31:0] alpha, output out_valid, output [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T_XD = 1 + L_MUL + L_XD, T_P = T_XD + 1 + L_MULW, LATENCY = T_P + 2 + L_OM15;
    reg [15:0] nl, nv, a;
    reg [31:0] xl1, dl1, xv1, dv1, yl1, yv1;
    reg [63:0] den, pxd, den2, num;
    wire [31:0] a2, xl, dl, xv, dv;
    wire [15:0] nl2, nv2;
    wire [63:0] pdd, pxx, pyy;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
        xl1 <= xl;                                                      // T_XD + 1
        dl1 <= dl;
        xv1 <= xv;
        dv1 <= dv;
        yl1 <= dl - xl;
        yv1 <= dv - xv;
        den <= UNC ? pdd : pdd - pyy;                                   // T_P + 1
        pxd <= pxx;
        den2 <= den;                                                    // T_P + 2
        num <= den - pxd;
    end
    fx_mul #(16, 16) ma (clk, {16'd0, a}, {16'd0, a}, a2);
    fx_delay #(32, L_MUL) dn (clk, {nl, nv}, {nl2, nv2});
    fx_smith_xd sl (clk, nl2, a2, xl, dl);                                  // at T_XD
    fx_smith_xd sv (clk, nv2, a2, xv, dv);
    fx_mulw #(32, 32) m1 (clk, dl1, dv1, pdd);                              // at T_P
    fx_mulw #(32, 32) m2 (clk, xl1, xv1, pxx);
    generate
        if (UNC) begin : g_unc
            assign pyy = 64'd0;
        end else begin : g_cor
            fx_mulw #(32, 32) m3 (clk, yl1, yv1, pyy);
        end
    endgenerate
    fx_one_minus15 om (clk, num[63:32], den2[63:32], y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
