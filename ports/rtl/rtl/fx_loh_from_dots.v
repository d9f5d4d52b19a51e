// fx_loh_from_dots: L.H = sqrt((1 + l.v) / 2), Q15
// (facet_loh_from_dots_fx_fast).  Mirrors the body's loh_from_dots:
//   1: T = 2^15 + LOV clamped to [0, 2^16]
//   2: c = (max(T, 1) - 1) 2^16 + 2^16 - 1 (= T 2^16 - 1 for T >= 1)
//   L.H = s 2^-(20 + h) (fx_sqrt32); raw = round(s / 2^(5 + h)); T = 0 gives 0
module fx_loh_from_dots (input clk, input rst, input in_valid, input [31:0] lov, output out_valid,
                         output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 2 + L_SQRT32 + 2;
    reg [16:0] t;
    reg [31:0] c;
    reg tz, tz2;
    reg [31:0] vs;
    wire [31:0] rs;
    wire [3:0] rh;
    wire tzd;
    always @(posedge clk) begin
        t <= f_clamp_off(lov, -32768, 32768);
        c <= ((f_max({15'd0, t}, 32'd1) - 32'd1) << 16) + 32'hFFFF;
        tz <= t == 17'd0;
    end
    fx_sqrt32 sq (clk, c, rs, rh);
    fx_delay #(1, L_SQRT32) dz (clk, tz, tzd);
    wire [31:0] v = vs + 32'd1;
    always @(posedge clk) begin
        vs <= rs >> ({1'b0, rh} + 5'd4);                          // round(s / 2^(5 + h)): the shift,
        tz2 <= tzd;
        y <= tz2 ? 32'd0 : {1'b0, v[31:1]};                        // the rounding, T = 0
    end
    fx_valid #(LATENCY) vv (clk, rst, in_valid, out_valid);
endmodule
