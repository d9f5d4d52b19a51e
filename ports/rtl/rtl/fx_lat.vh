// fx_lat.vh - the latency of every shared unit (fx_units.v), in clocks from
// its inputs to its registered output; kernels align their side values with
// fx_delay by these numbers, so a unit's latency is stated once.  A stage
// holds at most one carry chain (an add or a compare) or one barrel shift,
// with a little select logic around it.
localparam L_MUL    = 1;                      // fx_mul: a 32-bit product of narrow operands (one DSP)
localparam L_MULW   = 3;                      // fx_mulw: 16x16 partial products; the middle sum; the total
localparam L_MULHI  = L_MULW;                 // fx_mulhi: the high word of fx_mulw
localparam L_TAB20  = 5;                      // fx_tab20: read, step, product, rounding, correction
localparam L_SQRT32 = 1 + L_TAB20;            // fx_sqrt32: even normalising shift, then fx_tab20
localparam L_TOP    = 1;                      // fx_top: the top 32 bits of a 64-bit value
localparam L_DIVB   = 1 + L_TAB20 + L_MULHI + 4; // fx_divb: normalise, rcp, product, 4 rounding stages
localparam L_DIVBN  = L_DIVB + 2 * L_MULHI;  // fx_divb NEWTON: the Newton step's two products before q
localparam L_P5     = 5;                      // fx_p5: x (1 + y + ... + y^4) by table
localparam L_Y5     = L_MUL + 2 * L_MULHI;    // fx_y5: (1 - x)^5 by three products
localparam L_DOTS   = 3;                      // fx_dots: the dot triple s, u, w, c
localparam L_HAMMON_M = 1 + L_MULW + 1 + L_TOP; // fx_hammon_m: Hammon's Smith denominator, top word
localparam L_R30    = L_MUL + L_MULW + 3 + L_TAB20 + 1; // fx_smith_r30: Smith's root r(x)
localparam L_SDEN   = L_R30 + L_MULW + 1 + L_TOP; // fx_smith_den: nv r(nl) + nl r(nv), top word
localparam L_XD     = L_R30 + 1 + L_MULW + 1 + L_TOP; // fx_smith_xd: the tops of X = 2n(n + r), X + Y
localparam L_OM15   = L_DIVBN + 1;            // fx_one_minus15: round(2^15 (1 - q / d))
// Hammon's diffuse pieces: inputs at two or three times (see each unit)
localparam L_ROUGH  = L_SQRT32 + 2 + 3 * L_MULHI; // fx_rough: from a, s, c to the rough term
localparam L_SHAPE  = L_ROUGH + 1;            // fx_shape: from nl, nv, a, s, c to the shape
localparam D_ALBEDO_SHAPE = L_MUL + L_MULHI + 1; // fx_albedo: the shape this much after a, albedo
localparam L_ALBEDO = D_ALBEDO_SHAPE + 1 + L_MULHI; // fx_albedo: from a, albedo to the term
// brdf_hammon's two halves (fx_brdf_geometry.v, fx_brdf_channel.v check theirs against these)
localparam L_BRDF_GEOM = 1 + L_DOTS + L_SQRT32 + 1 + L_TAB20 + 4 * L_MULHI;
localparam L_BRDF_CHAN = L_MULHI + 3 + 3 * L_MULHI + 6;
