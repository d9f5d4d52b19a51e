// fx_brdf_geometry: what brdf_hammon computes before f0 and albedo enter
// (the body's brdf_geometry), shared by the RGB form's three channels.
// Inputs raw at the clock edge 1; every output lane at G = LATENCY:
//   the dot triple s, u, w, c (fx_dots); L.H = ls 2^-(20 + h) (fx_sqrt32);
//     k = 2h, x = c 2^k (2t = x 2^-(30 + k))
//   Fresnel's y = 1 - L.H = u 2^-32 / (1 + L.H): r1 = rcp20((1 + L.H) Q31),
//     u 2^ku normalised (u = 0 read as 1), ym = hi(u 2^ku, r1 2^12),
//     y5 = hi(hi(hi(ym, ym), ...), ym) (y^5 = y5 2^-(32 + 5 ku)), k5 = 5 ku
//   (a 2t)^2: ka = clz A, a2t = hi(A 2^ka, x), g2 = hi(a2t, a2t)
//   e^2 m: e60 = (A S)^2 + w 2^30 exact, its top word (fx_top, ee);
//     m30 = hi(2 NL NV, (2^15 - A) 2^17) + A S normalised (em, +17);
//     dm = hi(hi(et, et), mt), kd = clz dm, rd = rcp20(dm 2^kd)
//   the diffuse shape Q25 (fx_shape, Hammon's smooth term)
module fx_brdf_geometry (input clk, input [31:0] nol, input [31:0] nov, input [31:0] lov, input [31:0] alpha,
                         output [15:0] g_a, output [31:0] g_y5, output [7:0] g_k5, output [4:0] g_ka,
                         output [4:0] g_k, output [31:0] g_g2, output [5:0] g_ee, output [5:0] g_em,
                         output [5:0] g_kd, output [31:0] g_rd, output [31:0] g_shape);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    // the times of the lanes: the dots, L.H, x and k, r1, ym, y5 (= G);
    // A S, e's top word, m normalised, dm normalised, rd; the shape
    localparam T_DOTS = 1 + L_DOTS, T_SQ = T_DOTS + L_SQRT32, T_X = T_SQ + 1, T_R1 = T_X + L_TAB20;
    localparam T_YM = T_R1 + L_MULHI, T_Y5 = T_YM + 3 * L_MULHI;
    localparam TAS = T_DOTS + L_MUL, TE = TAS + L_MULW + 1 + L_TOP, TM = TAS + 2, TKD = TE + 2 * L_MULHI + 1;
    localparam TRD = TKD + L_TAB20, TSH = T_DOTS + L_SHAPE, TG2 = T_X + 2 * L_MULHI;
    localparam LATENCY = T_Y5;
    generate
        if (LATENCY != L_BRDF_GEOM) begin : g_check
            fx_latency_mismatch_L_BRDF_GEOM error ();
        end
    endgenerate
    reg [15:0] nl, nv, a, oma;
    reg [31:0] lov1, x, m1, uu, un, mt0, mt;
    reg [5:0] ku, em, kd;
    reg [7:0] k5;
    reg [4:0] k, ka;
    reg [31:0] an, dn;
    reg [63:0] e60;
    wire [16:0] s;
    wire [31:0] u, w, c, c9, ls, r1, und, ym, y2, y4, y5, ymd, an10, a2t, g2, as, wd, nn;
    wire [31:0] mt1, mt1d, mtd, et, e2, dm, rd, shape;
    wire [63:0] asq;
    wire [5:0] ee;
    wire [3:0] h;
    wire [15:0] nl4, nv4, a4, omad;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        a <= f_alpha(alpha);
        oma <= 32'd32768 - f_alpha(alpha);
        lov1 <= lov;
        // T_X: k, x, and (1 + L.H) Q31 for the reciprocal
        k <= {h, 1'b0};
        x <= c9 << {h, 1'b0};
        m1 <= 32'h80000000 + (ls << (4'd11 - h));
        // T_DOTS + 1, + 2: u normalised
        uu <= f_max(u, 32'd1);
        ku <= f_clz(uu);
        un <= uu << f_clz(uu);
        k5 <= {ku, 2'b00} + ku;
        // 2: A normalised
        ka <= f_clz(a);
        an <= {16'd0, a} << f_clz(a);
        // e^2 m
        e60 <= asq + {2'd0, wd, 30'd0};
        mt0 <= mt1d + as;
        em <= f_clz(mt0);
        mt <= mt0 << f_clz(mt0);
        kd <= f_clz(dm);
        dn <= dm << f_clz(dm);
    end
    fx_dots dots (clk, nl, nv, lov1, s, u, w, c);                         // at T_DOTS
    fx_sqrt32 sq (clk, c, ls, h);                                         // at T_SQ
    fx_delay #(32, L_SQRT32) dc (clk, c, c9);
    // Fresnel's y^5
    fx_tab20 #(0) rcp1 (clk, m1, r1);                                     // at T_R1
    fx_delay #(32, T_R1 - (T_DOTS + 2)) dun (clk, un, und);
    fx_mulhi #(32, 20, 12) mym (clk, und, r1, ym);                        // at T_YM
    fx_mulhi #(32, 32, 0) my2 (clk, ym, ym, y2);
    fx_mulhi #(32, 32, 0) my4 (clk, y2, y2, y4);
    fx_delay #(32, 2 * L_MULHI) dym (clk, ym, ymd);
    fx_mulhi #(32, 32, 0) my5 (clk, y4, ymd, y5);                         // at T_Y5
    // (a 2t)^2
    fx_delay #(32, T_X - 2) dan (clk, an, an10);
    fx_mulhi #(32, 32, 0) ma2 (clk, an10, x, a2t);
    fx_mulhi #(32, 32, 0) mg2 (clk, a2t, a2t, g2);                        // at TG2
    // e^2 m
    fx_delay #(16, L_DOTS) da4 (clk, a, a4);
    fx_mul #(16, 17) mas (clk, {16'd0, a4}, {15'd0, s}, as);              // A S at TAS
    fx_mulw #(32, 32) mee (clk, as, as, asq);
    fx_delay #(32, TAS + L_MULW - T_DOTS) dw (clk, w, wd);
    fx_top tp (clk, e60, et, ee);                                         // at TE
    fx_mul #(16, 16) mnn (clk, {16'd0, nl}, {16'd0, nv}, nn);
    fx_delay #(16, 1) doma (clk, oma, omad);
    fx_mulhi #(31, 16, 18) mm1 (clk, nn, {16'd0, omad}, mt1);             // hi(2 NL NV, (2^15 - A) 2^17)
    fx_delay #(32, TAS - (1 + L_MUL + L_MULHI)) dmt (clk, mt1, mt1d);
    fx_mulhi #(32, 32, 0) me2 (clk, et, et, e2);
    fx_delay #(32, TE + L_MULHI - TM) dmtd (clk, mt, mtd);
    fx_mulhi #(32, 32, 0) mdm (clk, e2, mtd, dm);
    fx_tab20 #(0) rcpd (clk, dn, rd);                                     // at TRD
    // the diffuse shape
    fx_delay #(32, L_DOTS) d4 (clk, {nl, nv}, {nl4, nv4});
    fx_shape #(0) sh (clk, nl4, nv4, a4, s, c, ls[19:0], h, x, k, shape); // at TSH
    // every lane to G
    fx_delay #(16, LATENCY - 1) o1 (clk, a, g_a);
    assign g_y5 = y5;
    fx_delay #(8, LATENCY - (T_DOTS + 3)) o2 (clk, k5, g_k5);
    fx_delay #(5, LATENCY - 2) o3 (clk, ka, g_ka);
    fx_delay #(5, LATENCY - T_X) o4 (clk, k, g_k);
    fx_delay #(32, LATENCY - TG2) o5 (clk, g2, g_g2);
    fx_delay #(6, LATENCY - TE) o6 (clk, ee, g_ee);
    fx_delay #(6, LATENCY - TM) o7 (clk, em + 6'd17, g_em);
    fx_delay #(6, LATENCY - (TKD)) o8 (clk, kd, g_kd);
    fx_delay #(32, LATENCY - TRD) o9 (clk, rd, g_rd);
    fx_delay #(32, LATENCY - TSH) o10 (clk, shape, g_shape);
endmodule
