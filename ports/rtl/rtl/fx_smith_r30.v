// fx_smith_r30: Smith's root r(x) = sqrt(a^2 (1 - x)(1 + x) + x^2), Q30 (the
// body's smith_r30): w60 = A^2 (2^15 - X)(2^15 + X) + X^2 2^30 exact in 64
// bits [2^40 .. 2^60]; its top word (fx_top, w = top 2^-E, E = 28 + e); the
// exponent made even by top >> (E & 1); the sqrt table (s = sq 2^-(4 + H),
// H = E >> 1); r = sq 2^(26 - H).  x (16 bits) and a2 = A^2 at T, r30 at
// T + L_R30.
module fx_smith_r30 (input clk, input [15:0] x, input [31:0] a2, output reg [31:0] r);
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
    fx_smith_r30 ul (clk, nl, a2, rl);
    fx_smith_r30 uv (clk, nv, a2, rv);
    fx_delay #(32, L_R30) d (clk, {nl, nv}, {nld, nvd});
    fx_mulw #(16, 32) m1 (clk, {16'd0, nvd}, rl, ml);
    fx_mulw #(16, 32) m2 (clk, {16'd0, nld}, rv, mv);
    fx_top tp (clk, den, dt, e);
endmodule
