// fx_g_kelemen: Kelemen's G = min(1, N.L N.V / V.H^2), Q15
// (facet_g_kelemen_fx_fast).  Mirrors the body's g_kelemen: p = NL NV and
// q = VH^2 exact Q30, p / max(q, 1) by one fx_divb (s = 15: b = 80), taken
// where p < q, else 1.
module fx_g_kelemen (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                     input [31:0] voh, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T3 = 1 + L_MUL + 1, LATENCY = T3 + L_DIVB + 1;
    reg [15:0] nl, nv, vh;
    reg [31:0] p3, q3;
    reg lt3;
    wire [31:0] p, q, g;
    wire ltd;
    always @(posedge clk) begin
        nl <= f_cos(nol);
        nv <= f_cos(nov);
        vh <= f_unit(voh);
        p3 <= p;
        q3 <= f_max(q, 32'd1);
        lt3 <= p < q;
        y <= ltd ? g : 32'd32768;
    end
    fx_mul #(16, 16) mp (clk, {16'd0, nl}, {16'd0, nv}, p);
    fx_mul #(16, 16) mq (clk, {16'd0, vh}, {16'd0, vh}, q);
    fx_divb #(32768) dv (clk, p3, q3, 32'd80, g);
    fx_delay #(1, L_DIVB) dl (clk, lt3, ltd);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
