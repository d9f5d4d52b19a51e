// fx_diffuse_burley: Burley's diffuse, albedo / pi (1 + (fd - 1) yl^5)(1 +
// (fd - 1) yv^5), fd = 0.5 + 2 sqrt(a) L.H^2, UQ8.24
// (facet_diffuse_burley_fx_fast).  Mirrors the body's diffuse_burley:
//   sqrt(a) Q19: A 2^ka in [2^30, 2^32), ka odd, the sqrt table, >> (ka - 15) / 2
//   fd Q29 = 2^28 + hi(sq 2^12, LH^2 2^1)
//   each factor Q29 = (2^30 - y5) / 2 + hi(2 fd, 2 y5), y5 by fx_y5
//   pr Q28 = hi(2 fl, 2 fv); d Q30 = hi(2 pr, albedo / pi Q33); raw = round(d / 2^6)
module fx_diffuse_burley (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
    input [31:0] loh, input [31:0] alpha, input [31:0] albedo, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    `include "fx_consts.vh"
    localparam T_SQ = 3 + L_TAB20 + 1, T_FD = T_SQ + L_MULHI + 1, T_F = T_FD + L_MULHI + 1;
    localparam T_PR = T_F + L_MULHI, T_D = T_PR + L_MULHI, LATENCY = T_D + 1;
    reg [15:0] a, lh, nl, nv, alb, a2r;
    reg [4:0] ka, sh;
    reg [31:0] an, sq, fd, hl, hv, fl, fv;
    wire [31:0] s, lh2, lh2d, fdm, y5l, y5v, y5ld, y5vd, ml, mv, pr, ai, aid, d;
    wire [4:0] shd;
    always @(posedge clk) begin
        a <= f_alpha(alpha);
        lh <= f_unit(loh);
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        alb <= f_unit(albedo);
        ka <= ((f_clz({16'd0, a}) + 6'd1) & 6'd30) - 6'd1;                 // 2: odd, in [15, 25]
        a2r <= a;
        an <= {16'd0, a2r} << ka;                                           // 3
        sh <= (ka - 5'd15) >> 1;
        sq <= s >> shd;                                                     // T_SQ: sqrt(a) Q19
        fd <= 32'd268435456 + fdm;                                          // T_FD
        hl <= (32'd1073741824 - y5ld) >> 1;                                 // T_FD
        hv <= (32'd1073741824 - y5vd) >> 1;
        fl <= hld + ml;                                                     // T_F
        fv <= hvd + mv;
        y <= (d + 32'd32) >> 6;                                             // LATENCY
    end
    fx_tab20 #(1) t (clk, an, s);                                           // at 3 + L_TAB20
    fx_delay #(5, L_TAB20) dsh (clk, sh, shd);
    fx_mul #(16, 16) ml2 (clk, {16'd0, lh}, {16'd0, lh}, lh2);              // LH^2 Q30
    fx_delay #(32, T_SQ - 2) dl2 (clk, lh2, lh2d);
    fx_mulhi #(20, 31, 13) mfd (clk, sq, lh2d, fdm);
    fx_y5 yl (clk, 16'd32768 - nl, y5l);                                    // at 1 + L_Y5
    fx_y5 yv (clk, 16'd32768 - nv, y5v);
    fx_delay #(64, T_FD - 1 - (1 + L_Y5)) dy5 (clk, {y5l, y5v}, {y5ld, y5vd});
    wire [31:0] y5l2, y5v2, hld, hvd;
    fx_delay #(64, L_MULHI) dh (clk, {hl, hv}, {hld, hvd});
    fx_delay #(64, 1) dy6 (clk, {y5ld, y5vd}, {y5l2, y5v2});
    fx_mulhi #(31, 31, 2) mfl (clk, fd, y5l2, ml);                          // hi(2 fd, 2 y5)
    fx_mulhi #(31, 31, 2) mfv (clk, fd, y5v2, mv);
    fx_mulhi #(31, 31, 2) mpr (clk, fl, fv, pr);                            // at T_PR
    fx_mul #(16, 17) mai (clk, {16'd0, alb}, K_INV_PI, ai);                 // albedo / pi Q33
    fx_delay #(32, T_PR - 2) dai (clk, ai, aid);
    fx_mulhi #(31, 32, 1) md (clk, pr, aid, d);                             // at T_D
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
