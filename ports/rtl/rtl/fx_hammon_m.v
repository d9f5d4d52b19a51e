// fx_hammon_m: Hammon's Smith denominator m = (1 - a) 2 nl nv + a (nl + nv)
// as m45 = 2 NL NV (2^15 - A) + A S 2^15 exact in 64 bits, and its top word
// (the body's hammon_m): m45 ~ mt 2^(32 - e).  nl, nv, a and p = NL NV at
// T; mt, e at T + L_HAMMON_M.  Shared by smith_g2_hammon and smith_vis_hammon.
module fx_hammon_m (input clk, input [15:0] nl, input [15:0] nv, input [15:0] a, input [31:0] p,
                    output [31:0] mt, output [5:0] e);
    `include "fx_lat.vh"
    reg [16:0] s1;
    reg [15:0] a1, oma1;
    reg [31:0] p1;
    reg [63:0] m45;
    wire [31:0] as, asd;
    wire [63:0] m1;
    always @(posedge clk) begin
        s1 <= nl + nv;
        a1 <= a;
        oma1 <= 32'd32768 - a;
        p1 <= p;
        m45 <= {m1[62:0], 1'b0} + {17'd0, asd, 15'd0};
    end
    fx_mul #(16, 17) ma (clk, {16'd0, a1}, {15'd0, s1}, as);                 // A S at T + 2
    fx_mulw #(31, 16) mw (clk, p1, {16'd0, oma1}, m1);                        // NL NV (2^15 - A) at T + 3
    fx_delay #(32, 1 + L_MULW - 1 - L_MUL) d (clk, as, asd);
    fx_top tp (clk, m45, mt, e);
endmodule
