// fx_smith_vis_joint_approx: the joint approximation is Hammon's visibility,
// the same code and bits (facet_smith_vis_joint_approx_fx_fast).
module fx_smith_vis_joint_approx (input clk, input rst, input in_valid, input [31:0] nol, input [31:0] nov,
                                  input [31:0] alpha, output out_valid, output [31:0] y);
    fx_smith_vis_hammon k (clk, rst, in_valid, nol, nov, alpha, out_valid, y);
endmodule
