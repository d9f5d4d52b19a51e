// fx_brdf_channel: one colour channel of brdf_hammon from the geometry
// lanes (fx_brdf_geometry) and that channel's f0 and albedo (clamped), all
// at C0 (the body's brdf_channel):
//   F = f0 + (1 - f0) y^5 = fs 2^-(30 + jj), jj = min(5 ku, clz(F0) - 16),
//     ft = hi(y5, (2^15 - F0) 2^16), fs = F0 2^(jj + 15) + ft >> (k5 + 1 - jj),
//     normalised by kF
//   spec = sp 2^-Es: num = hi(g2, fs 2^kF), sp = hi(hi(num, rd 2^12), 2^32 / 2pi),
//     normalised by ks; Es = 2 (ka + k) + jj + kF + ks + 18 - 2 ee - em - kd,
//     held biased by 256
//   spec Q29 = (sp >> sr) << sl (the C's product by 2^sl), sl <= 30 (checked)
//   diffuse Q26 (fx_albedo) to Q29 plus half a Q26 unit: (2 d + 1) 4
//   raw UQ40.24 = the Q29 sum rounded by 5 bits
module fx_brdf_channel (input clk, input [15:0] f0, input [15:0] omf, input [15:0] alb, input [15:0] g_a,
                        input [31:0] g_y5, input [7:0] g_k5, input [4:0] g_ka, input [4:0] g_k,
                        input [31:0] g_g2, input [5:0] g_ee, input [5:0] g_em, input [5:0] g_kd,
                        input [31:0] g_rd, input [31:0] g_shape, output reg [63:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam C2 = L_MULHI, C4 = C2 + 2, C6 = C4 + L_MULHI, C8 = C6 + L_MULHI, C10 = C8 + L_MULHI;
    localparam C14 = C10 + 4, CD = L_ALBEDO;            // spec at C14, the sum at C15
    localparam LATENCY = C14 + 2;
    reg [31:0] shr, sl13, jj, f01, k51, jj2, f02, k52, fs, fsn, sp, spn, es, sl, sr, sps, esp, d8;
    reg [5:0] kf4;
    reg [63:0] spec, sum;
    wire [31:0] ft, g2d, num, rdd, sp1, sp2, espd, shd, d, d64d;
    wire [4:0] kad, kd4;
    wire [5:0] eed, emd, kdd;
    wire [31:0] jj4;
    always @(posedge clk) begin
        // C1 .. C3: F
        jj <= f_min({24'd0, g_k5}, f_clz32({16'd0, f0}) - 32'd16);
        f01 <= {16'd0, f0};
        k51 <= {24'd0, g_k5};
        jj2 <= jj;
        f02 <= f01;
        k52 <= k51;
        fs <= (f02 << (jj2 + 32'd15)) + (ft >> f_min(k52 + 32'd1 - jj2, 32'd31));
        // C4: F normalised
        kf4 <= f_clz31(fs);
        fsn <= fs << f_clz31(fs);
        // C5: the exponent without ks
        esp <= {kad, 1'b0} + {kd4, 1'b0} + jj4 + kf4 + 32'd274 - ({eed, 1'b0} + emd + kdd);
        // C11: sp normalised, Es
        spn <= sp2 << f_clz31(sp2);
        es <= espd + f_clz31(sp2);
        // C12, C13, C14: the shifts to Q29
        sl <= 32'd285 - f_min(es, 32'd285);
        sr <= f_min(f_max(es, 32'd285) - 32'd285, 32'd31);
        sps <= spn;
        shr <= sps >> sr[4:0];
        sl13 <= sl;
        spec <= {32'd0, shr} << sl13[5:0];
        // the diffuse to Q29
        d8 <= {d[30:0], 1'b0} + 32'd1;
        sum <= spec + {30'd0, d64d, 2'b00};
        y <= (sum >> 5) + {63'd0, sum[4]};
    end
    fx_mulhi #(32, 16, 16) mft (clk, g_y5, {16'd0, omf}, ft);           // at C2
    fx_delay #(32, C4) dg2 (clk, g_g2, g2d);
    fx_mulhi #(32, 32, 0) mnum (clk, g2d, fsn, num);                    // at C6
    fx_delay #(32, C6) drd (clk, g_rd, rdd);
    fx_mulhi #(32, 20, 12) msp1 (clk, num, rdd, sp1);                   // at C8
    fx_mulhi #(32, 32, 0) msp2 (clk, sp1, K_INV_2PI, sp2);             // at C10
    fx_delay #(5, C4) dka (clk, g_ka, kad);
    fx_delay #(5, C4) dk (clk, g_k, kd4);
    fx_delay #(32, C4 - 2) djj (clk, jj2, jj4);
    fx_delay #(18, C4) dex (clk, {g_ee, g_em, g_kd}, {eed, emd, kdd});
    fx_delay #(32, C10 - (C4 + 1)) des (clk, esp, espd);
    fx_delay #(32, D_ALBEDO_SHAPE) dsh (clk, g_shape, shd);
    fx_albedo al (clk, g_a, alb, shd, d);                               // at CD
    fx_delay #(32, C14 - (CD + 1)) dd (clk, d8, d64d);
`ifndef SYNTHESIS
    always @(posedge clk)
        if (sl > 32'd31 && sps != 32'd0) $display("FX_WIDTH_ERROR %m: spec shift %0d", sl);
`endif
endmodule
