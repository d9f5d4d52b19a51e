// fx_lat.vh - the latency of every shared unit (fx_units.v), in clocks from
// its inputs to its registered output; kernels align their side values with
// fx_delay by these numbers, so a unit's latency is stated once.
localparam L_MUL    = 1;  // fx_mul: a 32-bit product of narrow operands
localparam L_MULW   = 2;  // fx_mulw: 16x16 partial products, then their sum
localparam L_MULHI  = 2;  // fx_mulhi: the high word of fx_mulw
localparam L_TAB20  = 4;  // fx_tab20: table read, step, multiply, interpolate
localparam L_SQRT32 = 5;  // fx_sqrt32: even normalising shift, then fx_tab20
localparam L_TOP    = 1;  // fx_top: the top 32 bits of a 64-bit value
localparam L_DIVB   = 9;  // fx_divb: normalise, rcp, multiply, round/saturate
localparam L_P5     = 5;  // fx_p5: x (1 + y + ... + y^4) by table
localparam L_Y5     = 5;  // fx_y5: (1 - x)^5 by three products
localparam L_DOTS   = 3;  // fx_dots: the dot triple s, u, w, c
// Hammon's diffuse pieces: inputs at two or three times (see each unit)
localparam L_ROUGH  = 13; // fx_rough: from a, s, c to the rough term
localparam L_SHAPE  = 14; // fx_shape: from nl, nv, a, s, c to the shape
localparam L_ALBEDO = 7;  // fx_albedo: from a, albedo (shape 4 later)
localparam D_ALBEDO_SHAPE = 4;
