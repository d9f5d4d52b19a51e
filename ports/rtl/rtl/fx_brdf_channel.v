// fx_brdf_channel: one colour channel of brdf_hammon from the geometry
// lanes (fx_brdf_geometry) and that channel's f0 and albedo (clamped), all
// at C0 (the body's brdf_channel):
//   F = f0 + (1 - f0) y^5 = fs 2^-(30 + jj), jj = min(5 ku, clz(F0) - 16),
//     ft = hi(y5, (2^15 - F0) 2^16), fs = F0 2^(jj + 15) + ft >> (k5 + 1 - jj),
//     normalised by kF
//   spec = sp 2^-Es: num = hi(g2, fs 2^kF), sp = hi(hi(num, rd 2^12), 2^32 / 2pi),
//     normalised by ks; Es = 2 (ka + k) + jj + kF + ks + 18 - 2 ee - em - kd,
//     held biased by 256 (its sum formed in two stages beside the products)
//   spec Q29 = (sp >> sr) << sl (the C's product by 2^sl), sl <= 30 (checked)
//   diffuse Q26 (fx_albedo) to Q29 plus half a Q26 unit: (2 d + 1) 4
//   raw UQ40.24 = the Q29 sum rounded by 5 bits: rshr(v, 5) = (v + 2^4) >> 5,
//     the 2^4 added to the diffuse term ((2 d + 5) 4), so one 64-bit add
module fx_brdf_channel (input clk, input [15:0] f0, input [15:0] omf, input [15:0] alb, input [15:0] g_a,
                        input [31:0] g_y5, input [7:0] g_k5, input [4:0] g_ka, input [4:0] g_k,
                        input [31:0] g_g2, input [5:0] g_ee, input [5:0] g_em, input [5:0] g_kd,
                        input [31:0] g_rd, input [31:0] g_shape, output reg [63:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    // ft; fs; fs normalised; the products num, sp1, sp2; sp normalised and
    // Es; the shifts; the sum
    localparam CF = L_MULHI, CS = CF + 2, CN = CS + 1, CP = CN + 3 * L_MULHI;
    localparam CD = L_ALBEDO;
    localparam LATENCY = CP + 6;
    generate
        if (LATENCY != L_BRDF_CHAN) begin : g_check
            fx_latency_mismatch_L_BRDF_CHAN error ();
        end
    endgenerate
    reg [31:0] jj1, f01, k51, sa2, sb2, f0s3, fts, f0sd, fs, fsn, a1, a2, esp, spn, es, d1, d2, sps, sl, sr;
    reg [31:0] shr, sl2, d64, sps2, f02;
    reg ge;
    reg [5:0] kf, kf7;
    reg [63:0] spec;
    wire [31:0] ft, g2d, num, rdd, sp1, sp2, espd, shd, d, d64d, sbd, f0s3d;
    wire [4:0] kad, kd4;
    wire [5:0] eed, emd, kdd;
    wire [31:0] jjd;
    always @(posedge clk) begin
        // 1 .. CS: F
        jj1 <= f_min({24'd0, g_k5}, f_clz32({16'd0, f0}) - 32'd16);                     // 1
        f01 <= {16'd0, f0};
        k51 <= {24'd0, g_k5};
        sa2 <= jj1 + 32'd15;                                                            // 2
        sb2 <= f_min(k51 + 32'd1 - jj1, 32'd31);
        f02 <= f01;
        f0s3 <= f02 << sa2;                                                             // 3
        fts <= ft >> sbd;                                                               // CF + 1
        f0sd <= f0s3d;
        fs <= f0sd + fts;                                                               // CS
        // CN: F normalised
        kf <= f_clz31(fs);
        fsn <= fs << f_clz31(fs);
        // the exponent without ks: CN + 1 .. CN + 2
        a1 <= {kad, 1'b0} + {kd4, 1'b0} + jjd + 32'd274;
        a2 <= {eed, 1'b0} + emd + kdd;
        kf7 <= kf;
        esp <= a1 + {26'd0, kf7} - a2;
        // CP + 1: sp normalised, Es
        spn <= sp2 << f_clz31(sp2);
        es <= espd + f_clz31(sp2);
        // CP + 2 .. CP + 4: the shifts to Q29, sl = 285 - min(Es, 285) and sr =
        // min(max(Es, 285) - 285, 31) from one compare and two differences
        ge <= es >= 32'd285;
        d1 <= 32'd285 - es;
        d2 <= es - 32'd285;
        sps <= spn;
        sps2 <= sps;
        sl <= ge ? 32'd0 : d1;
        sr <= !ge ? 32'd0 : |d2[31:5] ? 32'd31 : d2;
        shr <= sps2 >> sr[4:0];
        sl2 <= sl;
        spec <= {32'd0, shr} << sl2[5:0];                                              // CP + 5
        // the diffuse to Q29, plus the rounding's 2^4
        d64 <= {d[30:0], 1'b0} + 32'd5;                                                 // CD + 1
        y <= (spec + {30'd0, d64d, 2'b00}) >> 5;                                        // CP + 6
    end
    fx_mulhi #(32, 16, 16) mft (clk, g_y5, {16'd0, omf}, ft);                           // at CF
    fx_delay #(32, CF - 2) dsb (clk, sb2, sbd);
    fx_delay #(32, CF - 3) df0 (clk, f0s3, f0s3d);
    fx_delay #(32, CN) dg2 (clk, g_g2, g2d);
    fx_mulhi #(32, 32, 0) mnum (clk, g2d, fsn, num);                                    // at CN + L_MULHI
    fx_delay #(32, CN + L_MULHI) drd (clk, g_rd, rdd);
    fx_mulhi #(32, 20, 12) msp1 (clk, num, rdd, sp1);
    fx_mulhi #(32, 32, 0) msp2 (clk, sp1, K_INV_2PI, sp2);                             // at CP
    fx_delay #(5, CN) dka (clk, g_ka, kad);
    fx_delay #(5, CN) dk (clk, g_k, kd4);
    fx_delay #(32, CN - 1) djj (clk, jj1, jjd);
    fx_delay #(18, CN) dex (clk, {g_ee, g_em, g_kd}, {eed, emd, kdd});
    fx_delay #(32, CP - (CN + 2)) des (clk, esp, espd);
    fx_delay #(32, D_ALBEDO_SHAPE) dsh (clk, g_shape, shd);
    fx_albedo al (clk, g_a, alb, shd, d);                                               // at CD
    fx_delay #(32, CP + 5 - (CD + 1)) dd (clk, d64, d64d);
`ifndef SYNTHESIS
    always @(posedge clk)
        if (sl > 32'd31 && sps2 != 32'd0) $display("FX_WIDTH_ERROR %m: spec shift %0d", sl);
`endif
endmodule
