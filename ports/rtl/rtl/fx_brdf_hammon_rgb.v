// fx_brdf_hammon_rgb: brdf_hammon for three channels, UQ40.24 each
// (facet_brdf_hammon_rgb_fx_fast): the geometry once (fx_brdf_geometry),
// three fx_brdf_channel, so each channel is brdf_hammon's bits at that
// channel's f0 and albedo.  Inputs f0_r, albedo_r, f0_g, ... in that order.
module fx_brdf_hammon_rgb (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                           input [31:0] lov, input [31:0] alpha, input [31:0] f0_r, input [31:0] albedo_r,
                           input [31:0] f0_g, input [31:0] albedo_g, input [31:0] f0_b, input [31:0] albedo_b,
                           output out_valid, output [63:0] y_r, output [63:0] y_g, output [63:0] y_b);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam G = L_BRDF_GEOM, LATENCY = G + L_BRDF_CHAN;
    wire [15:0] g_a;
    wire [31:0] g_y5, g_g2, g_rd, g_shape;
    wire [7:0] g_k5;
    wire [4:0] g_ka, g_k;
    wire [5:0] g_ee, g_em, g_kd;
    wire [191:0] y3;
    wire [95:0] fin = {f0_b, f0_g, f0_r};
    wire [95:0] ain = {albedo_b, albedo_g, albedo_r};
    fx_brdf_geometry geo (clk, nol, nov, lov, alpha, g_a, g_y5, g_k5, g_ka, g_k, g_g2, g_ee, g_em, g_kd, g_rd,
                          g_shape);
    genvar i;
    generate
        for (i = 0; i < 3; i = i + 1) begin : g_ch
            reg [15:0] f0, omf, alb;
            wire [15:0] f0d, omfd, albd;
            always @(posedge clk) begin
                f0 <= f_unit(fin[32*i +: 32]);
                omf <= 32'd32768 - f_unit(fin[32*i +: 32]);
                alb <= f_unit(ain[32*i +: 32]);
            end
            fx_delay #(48, G - 1) dc (clk, {f0, omf, alb}, {f0d, omfd, albd});
            fx_brdf_channel ch (clk, f0d, omfd, albd, g_a, g_y5, g_k5, g_ka, g_k, g_g2, g_ee, g_em, g_kd, g_rd,
                                g_shape, y3[64*i +: 64]);
        end
    endgenerate
    assign y_r = y3[63:0];
    assign y_g = y3[127:64];
    assign y_b = y3[191:128];
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
