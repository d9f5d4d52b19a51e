// fx_fresnel_schlick: Schlick's Fresnel F = f0 + (1 - f0)(1 - cos)^5, Q15
// (facet_fresnel_schlick_fx_fast).  Mirrors the body's fresnel_schlick:
//   1: the unit clamps; Y = 2^15 - C
//   y^5 Q30 by fx_y5 (y2 = 2 Y^2, y4 = hi(y2, y2), y5 = hi(2 y4, Y 2^16))
//   t = hi(2 y5, (2^15 - F0) 2^16)            the (1 - f0) y^5 tail, Q30
//   raw = round((F0 2^15 + t) / 2^15)
module fx_fresnel_schlick (input clk, input rst, input in_valid, input [31:0] f0_in, input [31:0] cos_in,
                           output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 1 + L_Y5 + L_MULHI + 1;
    reg [15:0] f0, y1, omf;
    wire [31:0] y5, t;
    wire [15:0] omfd, f0d;
    always @(posedge clk) begin
        f0 <= f_unit(f0_in);
        y1 <= 32'd32768 - f_unit(cos_in);
        omf <= 32'd32768 - f_unit(f0_in);
    end
    fx_y5 u5 (clk, y1, y5);
    fx_delay #(16, L_Y5) d1 (clk, omf, omfd);
    fx_mulhi #(31, 16, 17) mt (clk, y5, {16'd0, omfd}, t);
    fx_delay #(16, L_Y5 + L_MULHI) d2 (clk, f0, f0d);
    always @(posedge clk) y <= ({1'b0, f0d, 15'd0} + t + 32'd16384) >> 15;
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
