// fx_ops.vh - the integer lane op layer in Verilog-2005: the combinational
// ops of the C's op layer (src/fx/fx_ops_scalar.h: clamps, min/max,
// compare, leading zeros), as functions a pipeline stage calls.  Included
// inside every module that uses them (Verilog functions are module-local).
// Products and table reads are not here: they are pipelined units
// (fx_units.v), as on silicon they are the stages' long paths.
// Unsigned 32-bit arithmetic wraps exactly as the C's uint32_t does.

// clamp a raw int32 to [lo, hi] (the domain clamp every kernel starts with)
function [31:0] f_clamp(input signed [31:0] x, input signed [31:0] lo, input signed [31:0] hi);
    f_clamp = x < lo ? lo : x > hi ? hi : x;
endfunction

// the same, offset so lo reads 0 (the dot triple's and L.V's t)
function [31:0] f_clamp_off(input signed [31:0] x, input signed [31:0] lo, input signed [31:0] hi);
    f_clamp_off = (x < lo ? lo : x > hi ? hi : x) - lo;
endfunction

// the three clamps of the inputs: cosines of two-cosine kernels to
// [cos floor, 1], unit inputs to [0, 1], alpha to [alpha floor, 1]
function [31:0] f_cos(input [31:0] x);
    f_cos = f_clamp(x, 128, 32768);
endfunction
function [31:0] f_unit(input [31:0] x);
    f_unit = f_clamp(x, 0, 32768);
endfunction
function [31:0] f_alpha(input [31:0] x);
    f_alpha = f_clamp(x, 32, 32768);
endfunction

function [31:0] f_min(input [31:0] a, input [31:0] b);
    f_min = a < b ? a : b;
endfunction
function [31:0] f_max(input [31:0] a, input [31:0] b);
    f_max = a > b ? a : b;
endfunction

// leading zeros of a 32-bit word, 32 for 0 (the op layer's clz): the
// binary search of the portable C, five halving steps
function [5:0] f_clz(input [31:0] a);
    reg [31:0] x;
    reg [5:0] n;
    begin
        x = a;
        n = 6'd0;
        if (x == 32'd0) n = 6'd32;
        else begin
            if (x[31:16] == 16'd0) begin n = n + 6'd16; x = x << 16; end
            if (x[31:24] == 8'd0)  begin n = n + 6'd8;  x = x << 8;  end
            if (x[31:28] == 4'd0)  begin n = n + 6'd4;  x = x << 4;  end
            if (x[31:30] == 2'd0)  begin n = n + 6'd2;  x = x << 2;  end
            if (x[31] == 1'b0)     begin n = n + 6'd1; end
        end
        f_clz = n;
    end
endfunction

// clz as a 32-bit lane value, and min(clz, 31) (the normalising shifts)
function [31:0] f_clz32(input [31:0] a);
    f_clz32 = {26'd0, f_clz(a)};
endfunction
function [31:0] f_clz31(input [31:0] a);
    f_clz31 = f_min({26'd0, f_clz(a)}, 32'd31);
endfunction
