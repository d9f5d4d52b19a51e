// fx_fresnel_schlick_sg: Schlick with the spherical-Gaussian power, f0 + (1 -
// f0) 2^-p, p = (5.55473 c + 6.98316) c, Q15
// (facet_fresnel_schlick_sg_fx_fast).  Mirrors the body's fresnel_schlick_sg:
//   p Q28 = hi(2 C^2, K1) + hi(C 2^16, K2)
//   2^-p = 2^-n 2^-f: the 257-entry Q31 table of 2^(-i/256) at f's top 8
//     bits (fx_rom_exp2, both neighbours in one word), its next 20 bits
//     interpolating (one high word), then >> n, n = p >> 28
//   F30 = F0 2^15 + hi((2^15 - F0) 2^16, E), raw = round(F30 / 2^15)
module fx_fresnel_schlick_sg (input clk, input rst, input in_valid, input [31:0] f0_in, input [31:0] cos_in,
    output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_P = 1 + L_MUL + L_MULHI + 1, T_E0 = T_P + 2, T_M = T_E0 + L_MULHI, T_E = T_M + 2;
    localparam T_T = T_E + L_MULHI, LATENCY = T_T + 1;
    reg [15:0] f0, c, omf;
    reg [31:0] p, e1d, e0d, ee, e;
    reg [19:0] fr7, fr8;
    reg [3:0] n7;
    wire [31:0] cc, m1, m2, m2d, m, e0m, t;
    wire [63:0] q;
    wire [3:0] nd;
    wire [15:0] omfd, f0d;
    always @(posedge clk) begin
        f0 <= f_unit(f0_in);
        c <= f_unit(cos_in);
        omf <= 32'd32768 - f_unit(f0_in);
        p <= m1 + m2d;                                                      // T_P
        fr7 <= p[19:0];                                                     // T_P + 1, with the ROM read
        n7 <= p[31:28];
        fr8 <= fr7;                                                         // T_E0
        e0d <= q[31:0];
        e1d <= q[31:0] - q[63:32];                                          // the step < 2^23
        ee <= e0m - m;                                                      // T_M + 1
        e <= ee >> nd;                                                      // T_E
        y <= ({1'b0, f0d, 15'd0} + t + 32'd16384) >> 15;                    // LATENCY
    end
    fx_mul #(16, 16) mc (clk, {16'd0, c}, {16'd0, c}, cc);                  // C^2 Q30
    fx_mulhi #(31, 32, 1) mk1 (clk, cc, K_SG_K1, m1);                       // at 1 + L_MUL + L_MULHI
    fx_mulhi #(16, 32, 16) mk2 (clk, {16'd0, c}, K_SG_K2, m2);              // at 1 + L_MULHI
    fx_delay #(32, L_MUL) dm2 (clk, m2, m2d);
    fx_rom_exp2 rom (clk, p[27:20], q);                                     // at T_P + 1
    fx_mulhi #(23, 20, 12) mi (clk, e1d, {12'd0, fr8}, m);                  // at T_M
    fx_delay #(32, L_MULHI) de0 (clk, e0d, e0m);
    fx_delay #(4, T_E - 1 - (T_P + 1)) dn (clk, n7, nd);
    fx_delay #(16, T_E - 1) domf (clk, omf, omfd);
    fx_mulhi #(16, 32, 16) mt (clk, {16'd0, omfd}, e, t);                   // at T_T
    fx_delay #(16, T_T - 1) df0 (clk, f0, f0d);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
