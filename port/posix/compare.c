/* SPDX-License-Identifier: MIT */
/* compare: image difference metrics, heat maps and `fixtrace compare`. */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include "compare.h"
#include "image_out.h"
#include "rt_render.h"

static int absdiff(uint8_t a, uint8_t b) { return a > b ? a - b : b - a; }

/* Largest channel difference at pixel index i. */
static int pixel_err(const ppm_image *a, const ppm_image *b, size_t i)
{
    int e = 0, c;
    for (c = 0; c < 3; c++) {
        int d = absdiff(a->data[3 * i + c], b->data[3 * i + c]);
        if (d > e)
            e = d;
    }
    return e;
}

/* Some channel spans more than COMPARE_EDGE_RANGE around (x, y) in img. */
static int at_edge(const ppm_image *img, int x, int y)
{
    int c, dx, dy;
    for (c = 0; c < 3; c++) {
        int lo = 255, hi = 0;
        for (dy = -1; dy <= 1; dy++) {
            for (dx = -1; dx <= 1; dx++) {
                int xx = x + dx, yy = y + dy, v;
                if (xx < 0 || yy < 0 || xx >= img->width || yy >= img->height)
                    continue;
                v = img->data[3 * ((size_t)yy * img->width + xx) + c];
                lo = v < lo ? v : lo;
                hi = v > hi ? v : hi;
            }
        }
        if (hi - lo > COMPARE_EDGE_RANGE)
            return 1;
    }
    return 0;
}

int compare_images(const ppm_image *a, const ppm_image *b, compare_result *r)
{
    size_t npix, i;
    double sq = 0, abs_sum = 0;
    int x, y, c;
    memset(r, 0, sizeof *r);
    if (a->width != b->width || a->height != b->height)
        return -1;
    r->width = a->width;
    r->height = a->height;
    npix = (size_t)a->width * (size_t)a->height;
    for (y = 0; y < a->height; y++) {
        for (x = 0; x < a->width; x++) {
            i = (size_t)y * a->width + x;
            for (c = 0; c < 3; c++) {
                int d = absdiff(a->data[3 * i + c], b->data[3 * i + c]);
                sq += (double)d * d;
                abs_sum += d;
            }
            int e = pixel_err(a, b, i);
            if (e > r->max_err)
                r->max_err = e;
            if (e > COMPARE_BAD_LEVEL)
                r->bad++;
            if (e > COMPARE_OUTLIER_LEVEL) {
                r->outliers++;
                if (!at_edge(b, x, y))
                    r->interior_outliers++;
            }
        }
    }
    r->mae = npix ? abs_sum / (3.0 * (double)npix) : 0;
    r->bad_pct = npix ? 100.0 * (double)r->bad / (double)npix : 0;
    if (sq == 0) {
        r->psnr = HUGE_VAL;
    } else {
        double mse = sq / (3.0 * (double)npix);
        r->psnr = 10.0 * log10(255.0 * 255.0 / mse);
    }
    return 0;
}

void compare_heat(int e, uint8_t rgb[3])
{
    static const double stop[5][3] = {
        {0, 0, 0}, {0, 0, 255}, {0, 255, 0}, {255, 255, 0}, {255, 0, 0}};
    double t, f;
    int seg, c;
    if (e <= 0) {
        rgb[0] = rgb[1] = rgb[2] = 0;
        return;
    }
    t = log2(1.0 + e) / 8.0 * 4.0; /* 0..4 across the four segments */
    if (t > 4)
        t = 4;
    seg = t >= 4 ? 3 : (int)t;
    f = t - seg;
    for (c = 0; c < 3; c++)
        rgb[c] = (uint8_t)floor(stop[seg][c] + f * (stop[seg + 1][c] -
                                                   stop[seg][c]) + 0.5);
}

int compare_heatmap(const ppm_image *a, const ppm_image *b, ppm_image *out)
{
    size_t i, npix;
    memset(out, 0, sizeof *out);
    if (a->width != b->width || a->height != b->height)
        return -1;
    if (ppm_alloc(out, a->width, a->height))
        return -1;
    npix = (size_t)a->width * (size_t)a->height;
    for (i = 0; i < npix; i++)
        compare_heat(pixel_err(a, b, i), out->data + 3 * i);
    return 0;
}

/* ---- The command ------------------------------------------------------- */

static void usage(FILE *f)
{
    fprintf(f,
            "usage: fixtrace compare A.ppm B.ppm [--diff DIFF.ppm|DIFF.png] "
            "[--min-psnr DB]\n"
            "                        [--max-bad PERCENT] "
            "[--max-interior-outliers N]\n"
            "  Compares two images of the same size, each a binary PPM or\n"
            "  an 8-bit RGB or grey PNG (fixtrace's own, or most others);\n"
            "  B is the reference (edges are judged on it).\n"
            "  --diff FILE    write a heat map of the error (black = equal,\n"
            "                 then blue, green, yellow, red), as PPM or as\n"
            "                 PNG by the name; never over A or B\n"
            "  --min-psnr DB  fail (exit 1) below this PSNR\n"
            "  --max-bad P    fail when more than P %% of pixels are off by "
            "more than %d/255\n"
            "  --max-interior-outliers N\n"
            "                 fail when more than N pixels away from B's "
            "edges (speckles)\n"
            "                 are off by more than %d/255\n"
            "  Exit status: 0 ok, 1 a threshold missed, 2 usage or input "
            "error.\n",
            COMPARE_BAD_LEVEL, COMPARE_OUTLIER_LEVEL);
}

/* Parses a whole argument as a number (not NaN). Returns 0 or -1. */
static int parse_num(const char *s, double *out)
{
    char *end;
    double v;
    if (!s || !*s)
        return -1;
    v = strtod(s, &end);
    if (*end != '\0' || v != v)
        return -1;
    *out = v;
    return 0;
}

typedef struct {
    const char *path[2];
    const char *diff;
    double min_psnr, max_bad, max_interior;
    int has_psnr, has_bad, has_interior;
} compare_args;

/* The diff image's name, as the render command checks its output: a
 * known image extension, not stdout (the metrics go there), and not one of
 * the images compared. Returns 0, or 2 after printing what is wrong. */
static int check_diff_name(const compare_args *a)
{
    struct stat d, in;
    if (strcmp(a->diff, "-") == 0 || image_kind_of(a->diff) == IMAGE_UNKNOWN ||
        image_kind_of(a->diff) == IMAGE_PANEL_PNM) {
        fprintf(stderr, "fixtrace compare: cannot write the diff image "
                "'%s': its name must end in .ppm or .png\n", a->diff);
        return 2;
    }
    if (stat(a->diff, &d) != 0)
        return 0;
    for (int i = 0; i < 2; i++) {
        if (stat(a->path[i], &in) == 0 && in.st_dev == d.st_dev &&
            in.st_ino == d.st_ino) {
            fprintf(stderr, "fixtrace compare: the diff image '%s' is the "
                    "input %s itself; name the diff with --diff NAME.png\n",
                    a->diff, a->path[i]);
            return 2;
        }
    }
    return 0;
}

/* Writes img to path (PPM or PNG, by its name) atomically. Returns 0, or
 * -1 with a message in err. */
static int save_image(const char *path, const ppm_image *img, char *err,
                      size_t errlen)
{
    image_out *o = image_out_open(path, img->width, img->height, RT_RGB888,
                                  0, err, errlen);
    if (!o)
        return -1;
    size_t stride = (size_t)img->width * 3;
    for (int y = 0; y < img->height; y++) {
        if (image_out_row(o, y, img->data + (size_t)y * stride, stride)) {
            snprintf(err, errlen, "internal error writing '%s'", path);
            image_out_abort(o);
            return -1;
        }
    }
    return image_out_commit(o, err, errlen);
}

/* Returns 0, or 2 after printing what is wrong. */
static int parse_args(int argc, char **argv, compare_args *a)
{
    int i, npath = 0;
    memset(a, 0, sizeof *a);
    for (i = 1; i < argc; i++) {
        const char *opt = argv[i];
        const char *val = i + 1 < argc ? argv[i + 1] : NULL;
        double v;
        if (strcmp(opt, "--diff") == 0) {
            if (!val || !*val) {
                fprintf(stderr, "fixtrace compare: --diff needs a file name\n");
                return 2;
            }
            a->diff = val;
            i++;
        } else if (strcmp(opt, "--min-psnr") == 0) {
            if (parse_num(val, &v)) {
                fprintf(stderr, "fixtrace compare: "
                                "--min-psnr needs a number of "
                                "dB\n");
                return 2;
            }
            a->min_psnr = v;
            a->has_psnr = 1;
            i++;
        } else if (strcmp(opt, "--max-bad") == 0) {
            if (parse_num(val, &v) || v < 0 || v > 100) {
                fprintf(stderr, "fixtrace compare: "
                                "--max-bad needs a percentage, "
                                "0 to 100\n");
                return 2;
            }
            a->max_bad = v;
            a->has_bad = 1;
            i++;
        } else if (strcmp(opt, "--max-interior-outliers") == 0) {
            if (parse_num(val, &v) || v < 0 || v != floor(v)) {
                fprintf(stderr, "fixtrace compare: "
                                "--max-interior-outliers needs a "
                                "whole number, 0 or more\n");
                return 2;
            }
            a->max_interior = v;
            a->has_interior = 1;
            i++;
        } else if (opt[0] == '-' && opt[1] != '\0') {
            fprintf(stderr, "fixtrace compare: unknown option %s\n", opt);
            usage(stderr);
            return 2;
        } else if (npath < 2) {
            a->path[npath++] = opt;
        } else {
            fprintf(stderr, "fixtrace compare: "
                            "more than two images given (%s)\n",
                    opt);
            usage(stderr);
            return 2;
        }
    }
    if (npath != 2) {
        fprintf(stderr, "fixtrace compare: needs two images\n");
        usage(stderr);
        return 2;
    }
    return a->diff ? check_diff_name(a) : 0;
}

static void print_result(const compare_args *a, const compare_result *r)
{
    printf("%s vs %s: %dx%d\n", a->path[0], a->path[1], r->width, r->height);
    if (isinf(r->psnr))
        printf("PSNR:            inf (identical)\n");
    else
        printf("PSNR:            %.2f dB\n", r->psnr);
    printf("max error:       %d/255\n", r->max_err);
    printf("mean abs error:  %.4f/255\n", r->mae);
    printf("off by > %d:      %.3f %% of pixels (%ld)\n", COMPARE_BAD_LEVEL,
           r->bad_pct, r->bad);
    printf("outliers (> %d): %ld pixels, %ld away from edges\n",
           COMPARE_OUTLIER_LEVEL, r->outliers, r->interior_outliers);
}

/* Checks the thresholds given; names each one missed. Returns 0 or 1. */
static int check_thresholds(const compare_args *a, const compare_result *r)
{
    int missed = 0;
    if (a->has_psnr && !(r->psnr >= a->min_psnr)) {
        fprintf(stderr, "fixtrace compare: "
                        "FAIL: PSNR %.2f dB is below --min-psnr "
                        "%g\n", r->psnr, a->min_psnr);
        missed = 1;
    }
    if (a->has_bad && r->bad_pct > a->max_bad) {
        fprintf(stderr, "fixtrace compare: "
                        "FAIL: %.3f %% of pixels off by > %d is "
                        "above --max-bad %g\n",
                r->bad_pct, COMPARE_BAD_LEVEL, a->max_bad);
        missed = 1;
    }
    if (a->has_interior && (double)r->interior_outliers > a->max_interior) {
        fprintf(stderr, "fixtrace compare: "
                        "FAIL: %ld outliers away from edges is "
                        "above --max-interior-outliers %.0f\n",
                r->interior_outliers, a->max_interior);
        missed = 1;
    }
    return missed;
}

int compare_main(int argc, char **argv)
{
    compare_args args;
    compare_result res;
    ppm_image img[2], heat;
    char err[512];
    int i, rc;
    for (i = 1; i < argc; i++) {
        if (strcmp(argv[i], "-h") == 0 || strcmp(argv[i], "--help") == 0) {
            usage(stdout);
            return 0;
        }
    }
    rc = parse_args(argc, argv, &args);
    if (rc)
        return rc;
    memset(img, 0, sizeof img);
    for (i = 0; i < 2; i++) {
        if (ppm_read(args.path[i], &img[i], err, sizeof err)) {
            fprintf(stderr, "fixtrace compare: %s\n", err);
            ppm_free(&img[0]);
            return 2;
        }
    }
    if (compare_images(&img[0], &img[1], &res)) {
        fprintf(stderr, "fixtrace compare: "
                        "sizes differ: %s is %dx%d, %s is %dx%d\n",
                args.path[0], img[0].width, img[0].height, args.path[1],
                img[1].width, img[1].height);
        ppm_free(&img[0]);
        ppm_free(&img[1]);
        return 2;
    }
    print_result(&args, &res);
    rc = check_thresholds(&args, &res);
    if (args.diff) {
        if (compare_heatmap(&img[0], &img[1], &heat)) {
            fprintf(stderr, "fixtrace compare: "
                            "out of memory for the diff image\n");
            rc = 2;
        } else if (save_image(args.diff, &heat, err, sizeof err)) {
            fprintf(stderr, "fixtrace compare: "
                            "cannot write the diff image: %s\n",
                    err);
            rc = 2;
        }
        ppm_free(&heat);
    }
    ppm_free(&img[0]);
    ppm_free(&img[1]);
    return rc;
}
