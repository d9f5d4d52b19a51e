/* sec_pictures.c - the pictures: BRDF slices, spheres and heat maps (pictures.c draws). */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "facet.h"
#include "report.h"

void section_pictures(report *r)
{
    pic p;
    int w;
    static const char *hm_file[PIC_N_HEATMAPS] = {
        "heat_vis_hammon.png", "heat_g2_uncorrelated.png", "heat_g1_hammon.png",
        "heat_lambert.png", "heat_brdf_hammon_model.png",
    };
    doc_heading(r->doc, 2, "%s", "Pictures");
    report_say("pictures: BRDF slices, spheres, heatmaps ...");
    p = pic_slices();
    report_picture(r, &p, "slices.png");
    pic_free(&p);
    p = pic_spheres();
    report_picture(r, &p, "spheres.png");
    pic_free(&p);
    for (w = 0; w < PIC_N_HEATMAPS; w++) {
        p = pic_heatmap(w);
        report_picture(r, &p, hm_file[w]);
        pic_free(&p);
    }
    p = pic_heatmap_f32();
    report_picture(r, &p, "heat_brdf_hammon_f32.png");
    pic_free(&p);
    p = pic_heatmap_fx(0);
    report_picture(r, &p, "heat_brdf_hammon_fx.png");
    pic_free(&p);
    p = pic_heatmap_fx(1);
    report_picture(r, &p, "heat_brdf_hammon_fx_inputs.png");
    pic_free(&p);
}

