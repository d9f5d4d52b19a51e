// fx_g_cook_torrance: Cook-Torrance's G = min(1, 2 N.H min(N.L, N.V) / V.H),
// Q15 (facet_g_cook_torrance_fx_fast).  Mirrors the body's g_cook_torrance:
// g = 2 NH min(NL, NV) Q30 exact; round(g / max(VH, 1)) by one fx_divb (s =
// 0: b = 95), taken where g < VH 2^15, else 1.
module fx_g_cook_torrance (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                           input [31:0] noh, input [31:0] voh, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam T2 = 1 + L_MUL, LATENCY = T2 + L_DIVB + 1;
    reg [15:0] vh, mn, vm, vh2, vm2;
    reg [16:0] nh2;
    reg lt3;
    wire [31:0] g, q;
    wire ltd;
    always @(posedge clk) begin
        vh <= f_unit(voh);
        vm <= f_max(f_unit(voh), 32'd1);
        nh2 <= {f_unit(noh), 1'b0};
        mn <= f_min(f_cos(nol), f_cos(nov));
        vh2 <= vh;
        vm2 <= vm;
        lt3 <= g < {1'b0, vh2, 15'd0};
        y <= ltd ? q : 32'd32768;
    end
    fx_mul #(17, 16) m (clk, {15'd0, nh2}, {16'd0, mn}, g);
    fx_divb #(32768) dv (clk, g, {16'd0, vm2}, 32'd95, q);
    fx_delay #(1, L_DIVB - 1) dl (clk, lt3, ltd);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
