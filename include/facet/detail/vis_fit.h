/* facet/detail/vis_fit.h - the constants of smith_vis_fit (facet.h), as
 * bench/fit/fit_vis.c fitted them: K1..K5 are 2 k1 .. 2 k5 (the kernel's
 * R = 2 r~, the 0.5 of Vis folded in), C1, C2 the coefficients of
 * sigma(a) = 1 + a (C1 + C2 a).  Part of the formula's definition: the
 * kernel body and the oracle both read them. */
#ifndef FACET_DETAIL_VIS_FIT_H
#define FACET_DETAIL_VIS_FIT_H
#define FACET_VIS_FIT_K1 2.06357503f
#define FACET_VIS_FIT_K2 0.60354346f
#define FACET_VIS_FIT_K3 1.96020985f
#define FACET_VIS_FIT_K4 1.60588074f
#define FACET_VIS_FIT_K5 1.28609383f
#define FACET_VIS_FIT_C1 0.076563403f
#define FACET_VIS_FIT_C2 -0.726259112f
#endif
