/* SPDX-License-Identifier: MIT */
/*
 * fixtrace: the host command. Renders a scene file to PPM (or PNG), with
 * the fixed-point core or the double reference; `fixtrace compare` compares
 * two images. Output goes to a temporary file that is renamed into place
 * only when the render succeeded, so a failed or interrupted render never
 * leaves a half image or harms an existing file.
 */
#include <errno.h>
#include <limits.h>
#include <pthread.h>
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <time.h>
#include <unistd.h>

#include "cli_util.h"
#include "compare.h"
#include "emit_c.h"
#include "mesh_obj.h"
#include "image_out.h"
#include "progress.h"
#include "receive.h"
#include "fixtrace_version.h"
#include "ref_render.h"
#include "rt_panel.h"
#include "rt_parse.h"
#include "rt_render.h"

static volatile sig_atomic_t interrupted;

static void on_signal(int sig)
{
    (void)sig;
    interrupted = 1;
}

typedef rt_status (*render_fn)(const rt_scene *, const rt_options *, int,
                               int, uint8_t *, rt_row_fn, void *, rt_stats *);

typedef struct {
    const char *scene_path;
    const char *out_path;
    long width, height, spp, depth, jobs, adaptive, draft;
    int stats, quiet, build_flags, emit_c;
    int reference; /* 0: the core; 1: the double reference; 2: float32 */
    const char *format; /* rgb888 (default), rgb565le, rgb565be, or a
                           panel's: mono, mono-page, grey4 */
    int dither;         /* 0, 1 ordered, 2 diffusion (panels only) */
    int trace_all;
    int window;         /* 1: only win[] = x0, y0, x1, y1 is rendered */
    long win[4];
} cli;

/* The panel format a --format name asks for, or -1 for an RGB one. */
static int panel_format(const char *f)
{
    return strcmp(f, "mono") == 0        ? RT_PANEL_MONO
           : strcmp(f, "mono-page") == 0 ? RT_PANEL_MONO_PAGE
           : strcmp(f, "grey4") == 0     ? RT_PANEL_GREY4
                                         : -1;
}

static void usage(FILE *f)
{
    fputs(
"NAME\n"
"    fixtrace - a Q16.16 fixed-point ray tracer for microcontrollers\n"
"\n"
"SYNOPSIS\n"
"    fixtrace [options] SCENE\n"
"    fixtrace compare A.ppm B.ppm [--diff D.ppm] [--min-psnr DB] [--max-bad PCT]\n"
"                     [--max-interior-outliers N]\n"
"    fixtrace receive -o OUT.png|OUT.ppm [-i INPUT] [-q]\n"
"\n"
"DESCRIPTION\n"
"    Renders the scene file SCENE (see docs/scene-format.md) and writes\n"
"    the image in the format its name ends with (any letter case):\n"
"      .ppm .pnm  binary PPM (P6), 8 bits a channel\n"
"      .png       PNG, 8 bits a channel\n"
"      .raw .bin  the rows exactly as --format makes them, no header: 3\n"
"                 bytes a pixel (rgb888) or 2 in the chosen byte order\n"
"                 (rgb565le, rgb565be), ready for a display\n"
"      .h         the same bytes as a C array (static const uint8_t\n"
"                 NAME[], with NAME_WIDTH and NAME_HEIGHT)\n"
"    The image is written to a temporary file beside the output and\n"
"    renamed into place only when the render succeeds.\n"
"\n"
"    fixtrace compare compares two images (fixtrace compare --help).\n"
"    fixtrace receive reads the firmware's UART output (make firmware\n"
"    OUTPUT=uart) from INPUT or stdin and writes its image once the\n"
"    frame's checksum holds (fixtrace receive --help).\n"
"\n"
"OPTIONS\n"
"    -o, --output FILE   output image (default: SCENE's name with .ppm, in\n"
"                        the current directory); - writes PPM to stdout\n"
"                        (a pipe or a file, never a terminal)\n"
"    -W, --width N       image width, 1..4096 (default: the scene's)\n"
"    -H, --height N      image height, 1..4096 (default: the scene's);\n"
"                        given alone, -W or -H keeps the scene's aspect\n"
"                        ratio (the other side is scaled, rounded)\n"
"    -s, --spp N         samples per pixel: 1, 4, 9 or 16 (default: the\n"
"                        scene's)\n"
"    -d, --depth N       reflection/refraction depth, 0..RT_MAX_DEPTH (5)\n"
"                        (default: the scene's)\n"
"    -j, --jobs N        render with N threads, 1..64 (default 1; the same\n"
"                        bytes as -j 1)\n"
"        --adaptive T    adaptive anti-aliasing: only pixels whose 3x3\n"
"                        neighbourhood differs by more than T (1..255, in\n"
"                        8-bit levels) get the full -s grid; needs -s > 1\n"
"        --draft T       draft render, about twice as fast: trace every\n"
"                        4th pixel of every 4th row, then each pixel\n"
"                        between only where its neighbours hit different\n"
"                        objects, textures or shadows, or differ by more\n"
"                        than T (1..255, in 8-bit levels; 64 is a good\n"
"                        start); the rest is interpolated. Composes with\n"
"                        -s and --adaptive\n"
"        --trace-all     trace every reflected and refracted ray to the\n"
"                        depth limit; by default rays too faint to move a\n"
"                        pixel by half an 8-bit level / spp, all of them\n"
"                        together, are skipped\n"
"        --reference     render with the double-precision reference\n"
"        --reference-float\n"
"                        render with the same reference built in float32\n"
"        --stats         print ray counters and timing on stderr\n"
"        --build-flags   print the -DRT_NO_* flags that remove every effect\n"
"                        the scene (at this spp) does not need, and exit;\n"
"                        when it needs them all, the line is empty and a\n"
"                        '# ... needs every effect' comment goes to stderr\n"
"        --emit-c        print the parsed scene as a C constant (for\n"
"                        firmware without the parser), and exit\n"
"        --format F      rows as rgb888 (default), rgb565le or rgb565be.\n"
"                        In a PPM or PNG, 565 rows are expanded back to 8\n"
"                        bits a channel (the top bits repeated below:\n"
"                        r5 -> r5 << 3 | r5 >> 2), so both byte orders\n"
"                        give the same file; .raw, .bin and .h keep the\n"
"                        565 bytes in the order chosen\n"
"        --dither [ordered|diffusion]\n"
"                        dithering: ordered (4x4 Bayer, the default) for\n"
"                        the 565 and panel formats; diffusion\n"
"                        (Floyd-Steinberg) for the panel formats only.\n"
"                        Without it panels take the nearest value\n"
"        --format mono|mono-page|grey4\n"
"                        a mono or 16-grey panel (docs/embedding.md):\n"
"                        .pbm/.pnm/.pgm or - write its picture (PBM for\n"
"                        mono, PGM with levels 0..15 for grey4); .raw and\n"
"                        .bin its bytes: mono rows MSB-first (1 = lit),\n"
"                        mono-page SSD1306 pages (8 rows a page, a byte a\n"
"                        column, bit 0 on top), grey4 two pixels a byte\n"
"                        (the first in the high nibble)\n"
"        --window X0,Y0,X1,Y1\n"
"                        render only columns X0..X1-1 of rows Y0..Y1-1 of\n"
"                        the frame, the same bytes as those pixels of the\n"
"                        whole render; the image is (X1-X0)x(Y1-Y0)\n"
"    -q, --quiet         no progress bar, no messages on success\n"
"    -h, --help          this text\n"
"        --version       print the version\n"
"\n"
"EXIT STATUS\n"
"    0 on success, 1 on a render or I/O error, 2 on bad usage or a bad\n"
"    scene, 130 when interrupted.\n"
"\n"
"EXAMPLES\n"
"    fixtrace scenes/seed.scene                  writes seed.ppm\n"
"    fixtrace -W 640 -H 480 -s 4 -o seed.png scenes/seed.scene\n"
"    fixtrace --reference -o ref.ppm scenes/seed.scene\n"
"    fixtrace -W 160 -H 128 --format rgb565be --dither -o lcd.raw SCENE\n"
"    fixtrace --draft 64 --stats scenes/seed.scene   a quick preview\n"
"    fixtrace compare seed.ppm ref.ppm --diff diff.ppm --min-psnr 40\n",
        f);
}

/* Default output: the scene's base name with ext (".ppm"), in the current
 * directory. */
static char *default_output(const char *scene, const char *ext)
{
    const char *base = strrchr(scene, '/');
    base = base ? base + 1 : scene;
    size_t n = strlen(base);
    const char *dot = strrchr(base, '.');
    if (dot && dot != base)
        n = (size_t)(dot - base);
    char *out = malloc(n + 5);
    if (!out)
        return NULL;
    memcpy(out, base, n);
    memcpy(out + n, ext, 5); /* a dot and three letters */
    return out;
}

static int parse_args(int argc, char **argv, cli *c)
{
    memset(c, 0, sizeof *c);
    c->jobs = 1;
    c->format = "rgb888";
    for (int i = 1; i < argc; i++) {
        const char *a = argv[i];
        const char *val = NULL;
#define TAKE(shortopt, longopt)                                               \
    ((strcmp(a, shortopt) == 0 || strcmp(a, longopt) == 0) &&                 \
     (val = cli_value(argc, argv, &i, a)) != NULL)
        if (strcmp(a, "-h") == 0 || strcmp(a, "--help") == 0) {
            usage(stdout);
            exit(0);
        } else if (strcmp(a, "--version") == 0) {
            printf("fixtrace %s (Q16.16, RT_MAX_DEPTH %d, RT_MAX_OBJECTS %d)\n",
                   FIXTRACE_VERSION_STRING, RT_MAX_DEPTH, RT_MAX_OBJECTS);
            exit(0);
        } else if (TAKE("-o", "--output")) {
            if (c->out_path)
                return cli_error("option %s given twice", a);
            if (!*val)
                return cli_error("%s needs a file name", a);
            c->out_path = val;
        } else if (TAKE("-W", "--width")) {
            if (cli_long(a, val, 1, RT_MAX_WIDTH, &c->width))
                return 2;
        } else if (TAKE("-H", "--height")) {
            if (cli_long(a, val, 1, RT_MAX_HEIGHT, &c->height))
                return 2;
        } else if (TAKE("-s", "--spp")) {
            if (cli_long(a, val, 1, 16, &c->spp))
                return 2;
            if (c->spp != 1 && c->spp != 4 && c->spp != 9 && c->spp != 16)
                return cli_error("%s must be 1, 4, 9 or 16 (got %s)", a, val);
        } else if (TAKE("-d", "--depth")) {
            if (cli_long(a, val, 0, RT_MAX_DEPTH, &c->depth))
                return 2;
            c->depth++; /* stored +1 so 0 means "scene default" */
        } else if (strcmp(a, "--adaptive") == 0 &&
                   (val = cli_value(argc, argv, &i, a)) != NULL) {
            if (cli_long(a, val, 1, 255, &c->adaptive))
                return 2;
        } else if (strcmp(a, "--draft") == 0 &&
                   (val = cli_value(argc, argv, &i, a)) != NULL) {
            if (cli_long(a, val, 1, 255, &c->draft))
                return 2;
        } else if (TAKE("-j", "--jobs")) {
            if (cli_long(a, val, 1, 64, &c->jobs))
                return 2;
        } else if (strcmp(a, "--format") == 0 &&
                   (val = cli_value(argc, argv, &i, a)) != NULL) {
            if (strcmp(val, "rgb888") && strcmp(val, "rgb565le") &&
                strcmp(val, "rgb565be") && panel_format(val) < 0)
                return cli_error("--format must be rgb888, rgb565le, "
                                 "rgb565be, mono, mono-page or grey4 (got "
                                 "'%s')", val);
            c->format = val;
        } else if (strcmp(a, "--dither") == 0) {
            c->dither = 1; /* the value is optional: only these words */
            if (i + 1 < argc && strcmp(argv[i + 1], "ordered") == 0)
                i++;
            else if (i + 1 < argc && strcmp(argv[i + 1], "diffusion") == 0)
                c->dither = 2, i++;
        } else if (strcmp(a, "--window") == 0 &&
                   (val = cli_value(argc, argv, &i, a)) != NULL) {
            char *end;
            const char *p = val;
            for (int k = 0; k < 4; k++) {
                errno = 0;
                c->win[k] = strtol(p, &end, 10);
                if (end == p || errno || c->win[k] < 0 ||
                    c->win[k] > RT_MAX_WIDTH || *end != (k < 3 ? ',' : '\0'))
                    return cli_error("--window needs X0,Y0,X1,Y1, four whole "
                                     "numbers from 0 (got '%s')", val);
                p = end + 1;
            }
            if (c->win[0] >= c->win[2] || c->win[1] >= c->win[3])
                return cli_error("--window %s is empty: X0 < X1 and Y0 < Y1 "
                                 "are needed", val);
            c->window = 1;
        } else if (strcmp(a, "--trace-all") == 0) {
            c->trace_all = 1;
        } else if (strcmp(a, "--stats") == 0) {
            c->stats = 1;
        } else if (strcmp(a, "-q") == 0 || strcmp(a, "--quiet") == 0) {
            c->quiet = 1;
        } else if (strcmp(a, "--reference") == 0) {
            c->reference = 1;
        } else if (strcmp(a, "--reference-float") == 0) {
            c->reference = 2;
        } else if (strcmp(a, "--build-flags") == 0) {
            c->build_flags = 1;
        } else if (strcmp(a, "--emit-c") == 0) {
            c->emit_c = 1;
        } else if (a[0] == '-' && a[1] != '\0') {
            if (cli_needs_value(a))
                return 2; /* cli_value already said what was missing */
            return cli_unknown_option(a);
        } else {
            if (c->scene_path)
                return cli_error("more than one scene given ('%s' and '%s')",
                                 c->scene_path, a);
            c->scene_path = a;
        }
#undef TAKE
    }
    if (!c->scene_path)
        return cli_error("no scene file given (try: fixtrace "
                         "scenes/seed.scene, or fixtrace --help)");
    if (c->adaptive && c->spp == 1)
        return cli_error("--adaptive needs -s 4, 9 or 16");
    if (c->dither && strcmp(c->format, "rgb888") == 0)
        return cli_error("--dither needs --format rgb565le, rgb565be, mono, "
                         "mono-page or grey4");
    if (c->dither == 2 && panel_format(c->format) < 0)
        return cli_error("--dither diffusion needs --format mono, mono-page "
                         "or grey4 (565 rows take ordered dithering)");
    if (c->window && c->reference)
        return cli_error("--window is a fixed-point core mode; the "
                         "reference renders whole rows");
    return 0;
}

/* Shared render state for the row callbacks and threads. */
typedef struct {
    const rt_scene *scene;
    rt_options opt;
    render_fn render;
    image_out *out;
    int progress;
    progress_eta eta;
    int rows_done;
    struct timespec start;
    uint64_t rays_so_far;
    pthread_mutex_t lock;
    int next_row;
    rt_status status;
    rt_stats stats;
    int x0, y0, x1, y1; /* the window rendered: the frame, or --window */
} job;

static double seconds_since(const struct timespec *t0)
{
    struct timespec t;
    clock_gettime(CLOCK_MONOTONIC, &t);
    return (double)(t.tv_sec - t0->tv_sec) +
           (double)(t.tv_nsec - t0->tv_nsec) * 1e-9;
}

static void show_progress(job *j, int final)
{
    static double last;
    double el = seconds_since(&j->start);
    if (!final && el - last < 0.1)
        return;
    last = el;
    int h = j->opt.height, done = j->rows_done;
    int bar = 30, fill = h ? done * bar / h : bar;
    double rate = el > 0 ? (double)j->rays_so_far / el : 0;
    double left = final ? 0 : progress_eta_left(&j->eta, el);
    fprintf(stderr, "\r[%.*s%*s] %3d%% rows %d/%d  %.2f Mrays/s  %s %.1fs ",
            fill, "##############################", bar - fill, "",
            h ? done * 100 / h : 100, done, h, rate / 1e6,
            final ? "took" : "left", final ? el : left);
    if (final)
        fputc('\n', stderr);
}

static int on_row(void *ctx, int y, const uint8_t *row, size_t n)
{
    job *j = ctx;
    int rc;
    pthread_mutex_lock(&j->lock);
    rc = image_out_row(j->out, y - j->y0, row, n);
    j->rows_done++;
    progress_eta_row(&j->eta, y);
    if (j->progress)
        show_progress(j, 0);
    pthread_mutex_unlock(&j->lock);
    return rc != 0 || interrupted;
}

static void add_stats(rt_stats *a, const rt_stats *b)
{
    a->primary += b->primary;
    a->shadow += b->shadow;
    a->reflection += b->reflection;
    a->refraction += b->refraction;
    a->tests += b->tests;
    a->cut += b->cut;
    a->interpolated += b->interpolated;
}

/* Rows a worker takes at a time: small enough to balance threads, large
 * enough that adaptive anti-aliasing rarely recomputes neighbour rows. A
 * draft band recomputes the coarse rows at its edges: it takes more. */
#define BAND_ROWS 8
#define DRAFT_BAND_ROWS 32

/* Worker: takes bands of rows in turn; rows do not depend on banding, so
 * the bytes equal a one-thread render. */
static void *worker(void *arg)
{
    job *j = arg;
    size_t nbytes = rt_window_bytes(&j->opt, (unsigned)(j->x1 - j->x0));
    uint8_t *row = malloc(nbytes);
    rt_stats st;
    memset(&st, 0, sizeof st);
    if (!row) {
        pthread_mutex_lock(&j->lock);
        j->status = RT_ERR_ARG;
        pthread_mutex_unlock(&j->lock);
        return NULL;
    }
    const int band = j->opt.draft ? DRAFT_BAND_ROWS : BAND_ROWS;
    for (;;) {
        pthread_mutex_lock(&j->lock);
        int y = j->status == RT_OK ? j->next_row : j->y1;
        j->next_row += band;
        j->rays_so_far = j->stats.primary + j->stats.shadow +
                         j->stats.reflection + j->stats.refraction;
        pthread_mutex_unlock(&j->lock);
        if (y >= j->y1)
            break;
        rt_stats row_st;
        memset(&row_st, 0, sizeof row_st);
        int y1 = y + band > j->y1 ? j->y1 : y + band;
        rt_status rc =
            j->x1 - j->x0 < j->opt.width
                ? rt_render_window(j->scene, &j->opt, j->x0, y, j->x1, y1,
                                   row, on_row, j, &row_st)
                : j->render(j->scene, &j->opt, y, y1, row, on_row, j,
                            &row_st);
        pthread_mutex_lock(&j->lock);
        add_stats(&j->stats, &row_st);
        if (rc != RT_OK && j->status == RT_OK)
            j->status = rc;
        pthread_mutex_unlock(&j->lock);
    }
    free(row);
    return NULL;
}

static const char *status_text(rt_status st)
{
    switch (st) {
    case RT_ERR_ARG:
        return "bad render options";
    case RT_ERR_UNSUPPORTED:
        return "the scene needs an effect this build removed";
    case RT_ERR_ABORTED:
        return "the output could not take a row";
    default:
        return "render error";
    }
}

/* -W and -H: both set the size; one alone scales the scene's other side
 * by the same factor (rounded, at least 1, at most the limit). */
static void apply_size(const cli *c, rt_options *o)
{
    long w = c->width, h = c->height;
    if (w && !h)
        h = (2L * w * o->height + o->width) / (2L * o->width);
    else if (h && !w)
        w = (2L * h * o->width + o->height) / (2L * o->height);
    if (w) {
        o->width = (uint16_t)(w < 1 ? 1 : w > RT_MAX_WIDTH ? RT_MAX_WIDTH : w);
        o->height =
            (uint16_t)(h < 1 ? 1 : h > RT_MAX_HEIGHT ? RT_MAX_HEIGHT : h);
    }
}

static int render_scene(const cli *c, const rt_scene *scene)
{
    job j;
    memset(&j, 0, sizeof j);
    j.scene = scene;
    rt_options_from_scene(&j.opt, scene);
    apply_size(c, &j.opt);
    if (c->spp)
        j.opt.spp = (uint8_t)c->spp;
    if (c->depth)
        j.opt.depth = (uint8_t)(c->depth - 1);
    j.opt.format = strcmp(c->format, "rgb565le") == 0   ? RT_RGB565_LE
                   : strcmp(c->format, "rgb565be") == 0 ? RT_RGB565_BE
                                                        : RT_RGB888;
    /* Panels take RGB888 rows, which rt_panel converts and dithers. */
    const int panel = panel_format(c->format);
    j.opt.dither = (uint8_t)(panel < 0 ? c->dither : 0);
    j.x0 = 0;
    j.y0 = 0;
    j.x1 = j.opt.width;
    j.y1 = j.opt.height;
    if (c->window) {
        if (c->win[2] > j.opt.width || c->win[3] > j.opt.height)
            return cli_error("--window %ld,%ld,%ld,%ld reaches past the "
                             "%dx%d frame", c->win[0], c->win[1], c->win[2],
                             c->win[3], j.opt.width, j.opt.height);
        j.x0 = (int)c->win[0];
        j.y0 = (int)c->win[1];
        j.x1 = (int)c->win[2];
        j.y1 = (int)c->win[3];
    }
    j.next_row = j.y0;
    j.opt.adaptive = (uint8_t)c->adaptive;
    j.opt.trace_all = (uint8_t)c->trace_all;
    j.opt.draft = (uint8_t)c->draft;
    if (c->adaptive && j.opt.spp == 1)
        return cli_error("--adaptive needs more than one sample per pixel; "
                         "%s renders at 1 spp, so add -s 4, 9 or 16",
                         c->scene_path);
    j.render = c->reference == 2 ? ref32_render_rows
               : c->reference ? ref_render_rows
                              : rt_render_rows;
    if (c->reference && c->adaptive)
        return cli_error("--adaptive is a fixed-point core mode; the "
                         "reference always takes every sample");
    if (c->reference && c->draft)
        return cli_error("--draft is a fixed-point core mode; the "
                         "reference always traces every pixel");
    /* The progress estimate is of whole frames. */
    j.progress = !c->quiet && isatty(STDERR_FILENO) && !c->window;
    pthread_mutex_init(&j.lock, NULL);

    uint32_t missing = rt_scene_features(scene, j.opt.spp) &
                       ~rt_build_features();
    if (missing && !c->reference) {
        fprintf(stderr, "fixtrace: %s: this build cannot render the "
                "scene's %s (it was built without it)\n", c->scene_path,
                rt_feature_name(missing & (0u - missing)));
        return 1;
    }

    char err[256];
    char *out_path =
        c->out_path ? NULL
                    : default_output(c->scene_path,
                                     panel < 0 ? ".ppm"
                                     : panel == RT_PANEL_GREY4 ? ".pgm"
                                                               : ".pbm");
    const char *path = c->out_path ? c->out_path : out_path;
    if (!path) {
        fprintf(stderr, "fixtrace: out of memory\n");
        return 1;
    }
    if (cli_check_output(path, c->scene_path) != 0) {
        free(out_path);
        return 2;
    }
    if (panel < 0 && image_kind_of(path) == IMAGE_PANEL_PNM) {
        cli_error("%s: a .pbm or .pgm output needs --format mono, "
                  "mono-page or grey4", path);
        free(out_path);
        return 2;
    }
    j.out = image_out_open(path, j.x1 - j.x0, j.y1 - j.y0, j.opt.format,
                           c->jobs > 1, err, sizeof err);
    if (!j.out) {
        fprintf(stderr, "fixtrace: %s\n", err);
        free(out_path);
        return 1;
    }
    if (panel >= 0 &&
        image_out_panel(j.out, panel, c->dither, j.x0, j.y0) != 0) {
        image_out_abort(j.out);
        cli_error("%s: --format %s writes .pbm, .pgm, .pnm, .ppm, .raw, "
                  ".bin or - (not PNG or .h)", path, c->format);
        free(out_path);
        return 2;
    }
    if (j.progress &&
        progress_eta_init(&j.eta, scene, &j.opt, j.render) != 0)
        j.progress = 0;
    clock_gettime(CLOCK_MONOTONIC, &j.start);
    j.status = RT_OK;
    if (c->jobs <= 1) {
        worker(&j);
    } else {
        pthread_t th[64];
        long started = 0;
        for (long t = 0; t < c->jobs; t++) {
            if (pthread_create(&th[t], NULL, worker, &j) != 0)
                break;
            started++;
        }
        if (started == 0)
            worker(&j);
        for (long t = 0; t < started; t++)
            pthread_join(th[t], NULL);
    }
    double secs = seconds_since(&j.start);
    if (j.progress && j.status == RT_OK)
        show_progress(&j, 1);
    else if (j.progress)
        fputc('\n', stderr);

    int rc = 0;
    if (j.status != RT_OK || interrupted) {
        image_out_abort(j.out);
        if (interrupted) {
            fprintf(stderr, "fixtrace: interrupted; %s was not written\n",
                    path);
            rc = 130;
        } else {
            fprintf(stderr, "fixtrace: render failed (%s); %s was not "
                    "written\n", status_text(j.status), path);
            rc = 1;
        }
    } else if (image_out_commit(j.out, err, sizeof err) != 0) {
        fprintf(stderr, "fixtrace: %s\n", err);
        rc = 1;
    } else if (!c->quiet && strcmp(path, "-") != 0) {
        fprintf(stderr, "fixtrace: wrote %s (%dx%d, %d spp%s)\n", path,
                j.x1 - j.x0, j.y1 - j.y0, j.opt.spp,
                c->reference == 2 ? ", float32 reference"
                : c->reference    ? ", reference"
                                  : "");
    }
    if (c->stats) {
        const uint64_t pixels =
            (uint64_t)(j.x1 - j.x0) * (uint64_t)(j.y1 - j.y0);
        fprintf(stderr, "pixels %llu\n", (unsigned long long)pixels);
        fprintf(stderr, "primary_rays %llu\n",
                (unsigned long long)j.stats.primary);
        fprintf(stderr, "shadow_rays %llu\n",
                (unsigned long long)j.stats.shadow);
        fprintf(stderr, "reflection_rays %llu\n",
                (unsigned long long)j.stats.reflection);
        fprintf(stderr, "refraction_rays %llu\n",
                (unsigned long long)j.stats.refraction);
        fprintf(stderr, "intersection_tests %llu\n",
                (unsigned long long)j.stats.tests);
        fprintf(stderr, "rays_cut %llu\n", (unsigned long long)j.stats.cut);
        fprintf(stderr, "traced_pixels %llu\n",
                (unsigned long long)(pixels - j.stats.interpolated));
        fprintf(stderr, "interpolated_pixels %llu\n",
                (unsigned long long)j.stats.interpolated);
        fprintf(stderr, "render_seconds %.6f\n", secs);
    }
    pthread_mutex_destroy(&j.lock);
    progress_eta_free(&j.eta);
    free(out_path);
    return rc;
}

/* The RT_NO_* flag of each feature bit, in bit order (rt_features.h). */
static const char *const no_flag[] = {
#define NO_FLAG(name, text) "RT_NO_" #name,
    RT_FEATURE_LIST(NO_FLAG)
#undef NO_FLAG
};

static int print_build_flags(const cli *c, const rt_scene *scene)
{
    uint8_t spp = c->spp ? (uint8_t)c->spp : scene->spp;
    uint32_t need = rt_scene_features(scene, spp);
    const char *sep = "";
    for (unsigned i = 0; i < sizeof no_flag / sizeof no_flag[0]; i++) {
        if (!(need & (1u << i))) {
            printf("%s-D%s", sep, no_flag[i]);
            sep = " ";
        }
    }
    printf("\n");
    /* The flags line stays empty so that $(fixtrace --build-flags) stays
     * a valid list; the note goes beside it. */
    if (!*sep && !c->quiet)
        fprintf(stderr, "# %s needs every effect at %u spp: no RT_NO_* "
                "flag applies\n", c->scene_path, (unsigned)spp);
    return 0;
}

int main(int argc, char **argv)
{
    if (argc > 1 && strcmp(argv[1], "compare") == 0)
        return compare_main(argc - 1, argv + 1);
    if (argc > 1 && strcmp(argv[1], "receive") == 0)
        return receive_main(argc - 1, argv + 1);

    cli c;
    int rc = parse_args(argc, argv, &c);
    if (rc)
        return rc;

    struct sigaction sa;
    memset(&sa, 0, sizeof sa);
    sa.sa_handler = on_signal;
    sigaction(SIGINT, &sa, NULL);
    sigaction(SIGTERM, &sa, NULL);
    sigaction(SIGHUP, &sa, NULL);
    signal(SIGPIPE, SIG_IGN);

    size_t len;
    char err[256];
    char *text = cli_read_file(c.scene_path, &len, err, sizeof err);
    if (!text) {
        fprintf(stderr, "fixtrace: %s\n", err);
        return 2;
    }
    static rt_scene scene;
    rt_parse_error pe;
    /* The meshes live until the process ends, as the scene does. */
    static mesh_obj_ctx meshes;
    mesh_obj_init(&meshes, c.scene_path, stderr, c.quiet);
    rt_status st = mesh_obj_parse_scene(text, len, c.scene_path, &scene, &pe,
                                        &meshes);
    if (st != RT_OK) {
        cli_print_parse_error(stderr, c.scene_path, text, len, &pe);
        free(text);
        return 2;
    }
    free(text);
    if (c.stats && meshes.n_mesh > 0)
        fprintf(stderr, "mesh_triangles %lu\nmesh_ignored_statements %lu\n",
                meshes.triangles, meshes.ignored);
    if (c.build_flags)
        return print_build_flags(&c, &scene);
    if (c.emit_c)
        return emit_c_scene(stdout, &scene, c.scene_path) == 0 ? 0 : 1;
    return render_scene(&c, &scene);
}
