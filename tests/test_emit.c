/* SPDX-License-Identifier: MIT */
/*
 * Round trip of `fixtrace --emit-c` (port/posix/emit_c.c): every scene in
 * scenes/ (and every parseable scene of the fuzz corpus, when present) is
 * parsed, written as C, compiled with the host compiler and read back.
 * The compiled constant must hold the parsed scene byte for byte (so a
 * field added to rt_scene.h but not to the emitter fails here, for any
 * scene that sets it), and the scenes of scenes/ must render the same
 * 32x24 image from it. The generated
 * file must also compile at capacities equal to the scene's counts, and
 * refuse to compile at smaller ones or under other settings.
 *
 * The test runs from the top of the tree (tests/run.sh does): it needs
 * core/ for the headers and scenes/. CC names the compiler (default cc).
 */
#include <dirent.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "harness.h"
#include "cli_util.h"
#include "emit_c.h"
#include "emit_dump.h"
#include "mesh_obj.h"
#include "rt_parse.h"
#include "rt_render.h"

#define MAX_SCENES 256
#define TW 32
#define TH 24

typedef struct {
    char path[256];
    rt_scene *scene;
} entry;

static entry list[MAX_SCENES];
static int count;
/* The meshes the scenes name, kept for the whole run. */
static mesh_obj_ctx meshes;
static char tmp[64];
static const char *cc;

static int cmp_entries(const void *a, const void *b)
{
    return strcmp(((const entry *)a)->path, ((const entry *)b)->path);
}

/* Adds every .scene of dir that parses; returns how many it added. With
 * must_parse, a scene that does not parse is a failure. */
static int add_dir(const char *dir, int must_parse)
{
    DIR *d = opendir(dir);
    struct dirent *de;
    int first = count, added = 0;
    if (!d)
        return 0;
    while ((de = readdir(d)) != NULL && count < MAX_SCENES) {
        size_t n = strlen(de->d_name);
        if (n > 6 && strcmp(de->d_name + n - 6, ".scene") == 0)
            snprintf(list[count++].path, sizeof list[0].path, "%s/%s", dir,
                     de->d_name);
    }
    closedir(d);
    qsort(list + first, (size_t)(count - first), sizeof list[0],
          cmp_entries);
    for (int i = first; i < count; i++) {
        char err[256];
        size_t len;
        rt_parse_error pe;
        char *text = cli_read_file(list[i].path, &len, err, sizeof err);
        rt_scene *s = malloc(sizeof *s);
        rt_status st = text && s ? mesh_obj_parse_scene(text, len,
                                                        list[i].path, s, &pe,
                                                        &meshes)
                                 : RT_ERR_ARG;
        free(text);
        if (st == RT_OK) {
            list[first + added].scene = s;
            if (first + added != i)
                memcpy(list[first + added].path, list[i].path,
                       sizeof list[0].path);
            added++;
            continue;
        }
        free(s);
        if (must_parse && !CHECK(st == RT_OK))
            printf("    %s does not parse\n", list[i].path);
    }
    count = first + added;
    return added;
}

/* Runs a shell command; its output goes to tmp/log. Returns its status. */
static int run(const char *cmd)
{
    char line[2048];
    snprintf(line, sizeof line, "%s >%s/log 2>&1", cmd, tmp);
    return system(line);
}

static void show_log(void)
{
    char path[128], buf[1024];
    snprintf(path, sizeof path, "%s/log", tmp);
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    buf[n] = '\0';
    if (f)
        fclose(f);
    printf("    %s\n", buf);
}

static int log_has(const char *what)
{
    char path[128], buf[4096];
    snprintf(path, sizeof path, "%s/log", tmp);
    FILE *f = fopen(path, "r");
    size_t n = f ? fread(buf, 1, sizeof buf - 1, f) : 0;
    buf[n] = '\0';
    if (f)
        fclose(f);
    return strstr(buf, what) != NULL;
}

/* The capacity, accuracy and depth settings of this build, which the
 * compiled tables must share to have the same layout and values. */
static void settings(char *buf, size_t n)
{
    snprintf(buf, n, "-DRT_MAX_OBJECTS=%d -DRT_MAX_MATERIALS=%d "
             "-DRT_MAX_LIGHTS=%d -DRT_MAX_DEPTH=%d -DRT_UNIT_BITS=%d",
             RT_MAX_OBJECTS, RT_MAX_MATERIALS, RT_MAX_LIGHTS, RT_MAX_DEPTH,
             RT_UNIT_BITS);
}

#define STRICT "-std=c99 -pedantic -Wall -Wextra -Werror -Wshadow -Wundef " \
               "-Wconversion -Icore/fx -Icore/scene -Icore/shapes -Icore/parse -Icore/frame"

/* Writes tmp/s<i>.c for every scene, and tmp/checker.c, which includes
 * them all under their own names and writes their bytes to argv[1]. */
static int write_sources(void)
{
    char path[128];
    FILE *f;
    for (int i = 0; i < count; i++) {
        snprintf(path, sizeof path, "%s/s%d.c", tmp, i);
        f = fopen(path, "w");
        if (!CHECK(f != NULL))
            return -1;
        CHECK_EQ(emit_c_scene(f, list[i].scene, list[i].path), 0);
        CHECK_EQ(fclose(f), 0);
    }
    snprintf(path, sizeof path, "%s/checker.c", tmp);
    f = fopen(path, "w");
    if (!CHECK(f != NULL))
        return -1;
    fprintf(f, "#include <stdio.h>\n#include \"emit_dump.h\"\n");
    for (int i = 0; i < count; i++)
        fprintf(f, "#define fw_scene fw_scene_%d\n#include \"s%d.c\"\n"
                "#undef fw_scene\n#undef FW_SCENE_OBJECTS\n"
                "#undef FW_SCENE_MATERIALS\n#undef FW_SCENE_LIGHTS\n", i, i);
    fprintf(f, "static const rt_scene *const all[] = {\n");
    for (int i = 0; i < count; i++)
        fprintf(f, "    &fw_scene_%d,\n", i);
    fprintf(f, "};\nint main(int argc, char **argv)\n{\n"
            "    FILE *f = argc > 1 ? fopen(argv[1], \"wb\") : NULL;\n"
            "    size_t n = sizeof all / sizeof all[0];\n"
            "    for (size_t i = 0; f && i < n; i++)\n"
            "        emit_dump(f, all[i]);\n"
            "    return !f || fclose(f) != 0;\n}\n");
    CHECK_EQ(fclose(f), 0);
    return 0;
}

static uint64_t hash;

static int hash_row(void *ctx, int y, const uint8_t *row, size_t nbytes)
{
    (void)ctx;
    hash = (hash ^ (uint64_t)y) * 0x100000001B3u;
    for (size_t i = 0; i < nbytes; i++)
        hash = (hash ^ row[i]) * 0x100000001B3u;
    return 0;
}

/* Renders s at TW x TH; the status, and the image's hash in *h. */
static rt_status render(const rt_scene *s, uint64_t *h)
{
    static uint8_t buf[TW * 12];
    rt_options o;
    rt_options_from_scene(&o, s);
    o.width = TW;
    o.height = TH;
    hash = 0xCBF29CE484222325u;
    rt_status st = rt_render_rows(s, &o, 0, TH, buf, hash_row, NULL, NULL);
    *h = hash;
    return st;
}

/* The compiled constants against the parsed scenes. */
static void check_round_trip(void)
{
    char cmd[1024], set[256], path[128];
    settings(set, sizeof set);
    snprintf(cmd, sizeof cmd, "%s " STRICT " -Itests %s -o %s/checker "
             "%s/checker.c", cc, set, tmp, tmp);
    if (!CHECK(run(cmd) == 0)) {
        show_log();
        return;
    }
    snprintf(cmd, sizeof cmd, "%s/checker %s/tables.bin", tmp, tmp);
    if (!CHECK(run(cmd) == 0)) {
        show_log();
        return;
    }
    snprintf(path, sizeof path, "%s/tables.bin", tmp);
    FILE *f = fopen(path, "rb");
    if (!CHECK(f != NULL))
        return;
    rt_scene *back = malloc(sizeof *back);
    for (int i = 0; back && i < count; i++) {
        const rt_scene *s = list[i].scene;
        /* The parsed scene's dump, then as many bytes of the compiled
         * one's. */
        char *want = NULL;
        size_t n = 0;
        FILE *mf = open_memstream(&want, &n);
        if (!CHECK(mf != NULL))
            break;
        emit_dump(mf, s);
        fclose(mf);
        unsigned char *got = malloc(n);
        if (!CHECK(got && fread(got, 1, n, f) == n)) {
            free(got);
            free(want);
            break;
        }
        const unsigned char *a = (const unsigned char *)want;
        size_t k = 0;
        while (k < n && a[k] == got[k])
            k++;
        if (!CHECK(k == n))
            printf("    %s: the compiled scene differs at byte %zu "
                   "(obj[0] is at %zu, mat[0] at %zu, light[0] at %zu; "
                   "meshes from %zu)\n",
                   list[i].path, k, offsetof(rt_scene, obj),
                   offsetof(rt_scene, mat), offsetof(rt_scene, light),
                   sizeof *s);
        /* The compiled scene back, its meshes the parsed ones (equal,
         * as the dumps are). */
        memcpy(back, got, sizeof *back);
        for (unsigned j = 0; j < back->n_objects && j < RT_MAX_OBJECTS; j++)
            if (back->obj[j].kind == RT_MESH)
                back->obj[j].u.mesh.tables = s->obj[j].u.mesh.tables;
        free(got);
        free(want);
        /* Rendering is for our own scenes: the fuzz corpus is there to
         * break the renderer (tests/suite_fuzz.sh), not this round trip. */
        if (strncmp(list[i].path, "scenes/", 7) != 0)
            continue;
        uint64_t h1, h2;
        rt_status st1 = render(s, &h1), st2 = render(back, &h2);
        CHECK_EQ(st2, st1);
        if (!CHECK(h1 == h2))
            printf("    %s: the compiled scene renders other bytes\n",
                   list[i].path);
    }
    free(back);
    fclose(f);
}

/* Scene i as the only unit, with extra -D options: 0 if it compiles. */
static int compile_alone(int i, const char *defs)
{
    char cmd[1024];
    snprintf(cmd, sizeof cmd, "%s " STRICT " %s -c -o %s/alone.o %s/s%d.c",
             cc, defs, tmp, tmp, i);
    return run(cmd);
}

/* Capacities equal to the counts are enough; one fewer, or another
 * accuracy or depth, is refused with a message naming the setting. */
static void check_guards(void)
{
    char defs[256];
    for (int i = 0; i < count; i++) {
        const rt_scene *s = list[i].scene;
        if (strncmp(list[i].path, "scenes/", 7) != 0)
            continue;
        int no = s->n_objects ? s->n_objects : 1;
        int nm = s->n_materials ? s->n_materials : 1;
        int nl = s->n_lights ? s->n_lights : 1;
        snprintf(defs, sizeof defs, "-DRT_MAX_OBJECTS=%d "
                 "-DRT_MAX_MATERIALS=%d -DRT_MAX_LIGHTS=%d", no, nm, nl);
        if (!CHECK(compile_alone(i, defs) == 0)) {
            printf("    %s at its own counts (%s):\n", list[i].path, defs);
            show_log();
        }
        if (no > 1) {
            snprintf(defs, sizeof defs, "-DRT_MAX_OBJECTS=%d", no - 1);
            CHECK(compile_alone(i, defs) != 0 && log_has("RT_MAX_OBJECTS"));
        }
    }
    snprintf(defs, sizeof defs, "-DRT_UNIT_BITS=%d",
             RT_UNIT_BITS > 16 ? RT_UNIT_BITS - 1 : RT_UNIT_BITS + 1);
    CHECK(compile_alone(0, defs) != 0 && log_has("RT_UNIT_BITS"));
    snprintf(defs, sizeof defs, "-DRT_MAX_DEPTH=%d", RT_MAX_DEPTH + 1);
    CHECK(compile_alone(0, defs) != 0 && log_has("RT_MAX_DEPTH"));
}

int main(void)
{
    cc = getenv("CC");
    if (!cc || !*cc)
        cc = "cc";
    snprintf(tmp, sizeof tmp, "/tmp/fixtrace-emit-XXXXXX");
    if (!CHECK(mkdtemp(tmp) != NULL))
        return th_summary();

    int own = add_dir("scenes", 1);
    CHECK(own >= 2);
    int extra = add_dir("tests/fuzz/corpus", 0);
    extra += add_dir("tests/fuzz/regressions", 0);
    printf("%d scenes from scenes/, %d from the fuzz corpus\n", own, extra);

    if (count > 0 && write_sources() == 0) {
        check_round_trip();
        check_guards();
    }

    char cmd[128];
    snprintf(cmd, sizeof cmd, "rm -rf %s", tmp);
    if (system(cmd) != 0)
        printf("could not remove %s\n", tmp);
    for (int i = 0; i < count; i++)
        free(list[i].scene);
    mesh_obj_free(&meshes);
    return th_summary();
}
