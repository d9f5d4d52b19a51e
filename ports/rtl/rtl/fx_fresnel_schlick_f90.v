// fx_fresnel_schlick_f90: Schlick with f90, f0 (1 - y^5) + f90 y^5, Q15
// (facet_fresnel_schlick_f90_fx_fast).  Mirrors the body's
// fresnel_schlick_f90: y^5 Q30 of y = 1 - V.H (fx_y5), then the convex
// combination hi(2 (2^30 - y5), F0 2^16) + hi(2 y5, F90 2^16) Q30, rounded.
module fx_fresnel_schlick_f90 (input clk, input rst, input in_valid, input [31:0] f0_in, input [31:0] f90_in,
                               input [31:0] voh, output out_valid, output reg [31:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam LATENCY = 1 + L_Y5 + 1 + L_MULHI + 1;
    reg [15:0] f0, f90, y1;
    reg [31:0] y5n, y5b;
    wire [31:0] y5, t0, t1;
    wire [15:0] f0d, f90d;
    always @(posedge clk) begin
        f0 <= f_unit(f0_in);
        f90 <= f_unit(f90_in);
        y1 <= 32'd32768 - f_unit(voh);
        y5n <= 32'd1073741824 - y5;
        y5b <= y5;
        y <= (t0 + t1 + 32'd16384) >> 15;
    end
    fx_y5 u5 (clk, y1, y5);
    fx_delay #(16, L_Y5 + 1) d0 (clk, f0, f0d);
    fx_delay #(16, L_Y5 + 1) d1 (clk, f90, f90d);
    fx_mulhi #(31, 16, 17) m0 (clk, y5n, {16'd0, f0d}, t0);
    fx_mulhi #(31, 16, 17) m1 (clk, y5b, {16'd0, f90d}, t1);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
