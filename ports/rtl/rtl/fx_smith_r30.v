// fx_smith_r30: Smith's root r(x) = sqrt(a^2 (1 - x)(1 + x) + x^2), Q30 (the
// body's smith_r30): w60 = A^2 (2^15 - X)(2^15 + X) + X^2 2^30 exact in 64
// bits [2^40 .. 2^60]; its top word (fx_top, w = top 2^-E, E = 28 + e); the
// exponent made even by top >> (E & 1); the sqrt table (s = sq 2^-(4 + H),
// H = E >> 1); r = sq 2^(26 - H).  x (16 bits) and a2 = A^2 at T, r30 at
// T + L_R30; y = A^2 (2^15 - X)(2^15 + X) (Y60 of fx_smith_xd) at T + L_MUL +
// L_MULW.
module fx_smith_r30 (input clk, input [15:0] x, input [31:0] a2, output reg [31:0] r, output [63:0] y);
    `include "fx_lat.vh"
    localparam T_W = L_MUL + L_MULW;                                   // L_R30 = T_W + 3 + L_TAB20 + 1
    reg [31:0] a21, ts;
    reg [63:0] w60;
    reg [4:0] hh;
    wire [31:0] w1, xx, xxd, tp, sq;
    wire [63:0] mw;
    wire [5:0] e;
    wire [4:0] hhd;
    wire [5:0] ee = e + 6'd28;
    always @(posedge clk) begin
        a21 <= a2;
        w60 <= mw + {2'd0, xxd, 30'd0};                                 // T_W + 1
        ts <= tp >> ee[0];                                              // T_W + 3
        hh <= ee[5:1];
        r <= sq << (5'd26 - hhd);                                       // L_R30
    end
    fx_mul #(16, 17) m1 (clk, {16'd0, 16'd32768 - x}, {15'd0, 17'd32768 + x}, w1); // (1 - x)(1 + x) Q30
    fx_mul #(16, 16) m2 (clk, {16'd0, x}, {16'd0, x}, xx);              // x^2 Q30
    fx_mulw #(31, 31) m3 (clk, a21, w1, mw);
    assign y = mw;
    fx_delay #(32, L_MULW) dx (clk, xx, xxd);
    fx_top tpu (clk, w60, tp, e);                                       // T_W + 2
    fx_tab20 #(1) t (clk, ts, sq);
    fx_delay #(5, L_TAB20) dh (clk, hh, hhd);
endmodule

// fx_smith_den: the height-correlated Smith denominator nv r(nl) + nl r(nv)
// in Q45, in 64 bits [< 2^46, >= 2^28], its top word dt ~ 2^(32 - e) (the
// body's g2_den), shared by smith_g2 and smith_vis.  nl, nv, a2 at T; dt, e
// at T + L_SDEN.
module fx_smith_den (input clk, input [15:0] nl, input [15:0] nv, input [31:0] a2, output [31:0] dt,
                     output [5:0] e);
    `include "fx_lat.vh"
    reg [63:0] den;
    wire [31:0] rl, rv;
    wire [15:0] nld, nvd;
    wire [63:0] ml, mv;
    always @(posedge clk) den <= ml + mv;
    wire [63:0] yl_unused, yv_unused;
    fx_smith_r30 ul (clk, nl, a2, rl, yl_unused);
    fx_smith_r30 uv (clk, nv, a2, rv, yv_unused);
    fx_delay #(32, L_R30) d (clk, {nl, nv}, {nld, nvd});
    fx_mulw #(16, 32) m1 (clk, {16'd0, nvd}, rl, ml);
    fx_mulw #(16, 32) m2 (clk, {16'd0, nld}, rv, mv);
    fx_top tp (clk, den, dt, e);
endmodule

// fx_smith_xd: the monotone form of the GGX Smith terms (the body's
// smith_xd): X60 = N 2^16 (N 2^15 + r30) = 2n (n + r) 2^60 [<= 2^62], Y60 =
// A^2 (2^15 - X)(2^15 + X) (fx_smith_r30's) [<= 2^60], D60 = X60 + Y60 [<
// 2^63, >= 2^40]; dt = D60's top word (fx_top's shift kk), xt = X60's at
// the same kk [xt <= dt].  x, a2 at T; xt, dt at T + L_XD.
module fx_smith_xd (input clk, input [15:0] x, input [31:0] a2, output reg [31:0] xt, output reg [31:0] dt);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    reg [31:0] den;
    reg [63:0] x60r, d60;
    wire [31:0] r;
    wire [15:0] xr;
    wire [63:0] y60, y60d, x60;
    wire [5:0] kk = f_clz31(d60[63:32]);
    always @(posedge clk) begin
        den <= {1'b0, xr, 15'd0} + r;                                   // L_R30 + 1
        d60 <= x60 + y60d;                                              // + L_MULW + 1
        x60r <= x60;
        dt <= (d60[63:32] << kk) | (d60[31:0] >> (6'd32 - kk));        // L_XD
        xt <= (x60r[63:32] << kk) | (x60r[31:0] >> (6'd32 - kk));
    end
    fx_smith_r30 sr (clk, x, a2, r, y60);
    fx_delay #(16, L_R30) dx (clk, x, xr);
    wire [15:0] xr1;
    fx_delay #(16, 1) dx1 (clk, xr, xr1);
    fx_mulw #(32, 32) mx (clk, {xr1, 16'd0}, den, x60);
    fx_delay #(64, L_R30 + 1 - L_MUL) dy (clk, y60, y60d);
`ifndef SYNTHESIS
    always @(posedge clk)
        if (d60[63] === 1'b1) $display("FX_WIDTH_ERROR %m: D60 %h (>= 2^63)", d60);
`endif
endmodule

// fx_one_minus15: round(2^15 (1 - q / d)) for q <= d (the body's
// one_minus15): c = round(q / d 2^31) by fx_divb NEWTON (b = 64, saturated
// at 2^31), then (2^31 - c + 2^15) >> 16.  q, d at T; y at T + L_OM15.
module fx_one_minus15 (input clk, input [31:0] q, input [31:0] d, output reg [31:0] y);
    wire [31:0] c;
    fx_divb #(32'h80000000, 1) dv (clk, q, d, 32'd64, c);
    always @(posedge clk) y <= (32'h80000000 - c + 32'h8000) >> 16;
endmodule
