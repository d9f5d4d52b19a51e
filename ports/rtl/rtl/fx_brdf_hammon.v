// fx_brdf_hammon: the whole model, spec + Hammon's diffuse, UQ40.24
// (facet_brdf_hammon_fx_fast): fx_brdf_geometry then one fx_brdf_channel
// (the body's brdf_hammon: the geometry, then the channel).
module fx_brdf_hammon (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                       input [31:0] lov, input [31:0] alpha, input [31:0] f0_in, input [31:0] albedo,
                       output out_valid, output [63:0] y);
    `include "fx_ops.vh"
    `include "fx_lat.vh"
    localparam G = L_BRDF_GEOM, LATENCY = G + L_BRDF_CHAN;
    reg [15:0] f0, omf, alb;
    wire [15:0] f0d, omfd, albd, g_a;
    wire [31:0] g_y5, g_g2, g_rd, g_shape;
    wire [7:0] g_k5;
    wire [4:0] g_ka, g_k;
    wire [5:0] g_ee, g_em, g_kd;
    always @(posedge clk) begin
        f0 <= f_unit(f0_in);
        omf <= 32'd32768 - f_unit(f0_in);
        alb <= f_unit(albedo);
    end
    fx_brdf_geometry geo (clk, nol, nov, lov, alpha, g_a, g_y5, g_k5, g_ka, g_k, g_g2, g_ee, g_em, g_kd, g_rd,
                          g_shape);
    fx_delay #(48, G - 1) dc (clk, {f0, omf, alb}, {f0d, omfd, albd});
    fx_brdf_channel ch (clk, f0d, omfd, albd, g_a, g_y5, g_k5, g_ka, g_k, g_g2, g_ee, g_em, g_kd, g_rd, g_shape,
                        y);
    fx_valid #(LATENCY) v (clk, rst, in_valid, out_valid);
endmodule
