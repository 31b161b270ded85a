/*
 * volpack_bench: times Debian's VolPack (libvolpack1-dev, shear-warp
 * software renderer, Lacroute & Levoy 1994) on a .den volume, as a speed
 * reference for the cube4 model.
 *
 * Usage:
 *   volpack_bench --den PATH [--size 256] [--rotate RX RY RZ] [--frames N]
 *                 [--warmup K] [--image FILE.ppm] [--gray]
 *                 [--max-ray-opacity A] [--volpack-view]
 *
 * Scene (follows VolPack's brainsmall example, without depth cueing):
 *   voxel = { 13-bit encoded normal, density, gradient magnitude } built by
 *   vpVolumeNormals; opacity = density ramp {0,24,255}->{0,1,1} times
 *   gradient ramp {0,5,20,221}->{0,0,1,1}; VP_MIN_VOXEL_OPACITY 0.05;
 *   VP_MAX_RAY_OPACITY 0.95 (early ray termination, as in the example;
 *   --max-ray-opacity 1 switches it off); one white directional light
 *   (0.3, 0.3, 1) in world space; lookup-table shader with one material
 *   (ambient 0.18, diffuse 0.35, specular 0.39, shininess 10, both sides);
 *   parallel projection; image size x size, RGB (or luminance with --gray).
 *
 * View, default ("view": "cube4", as golden/view.cpp had it when this was
 * written): the model (object -> world) matrix is
 *     M = Rz(RZ) * Ry(RY) * Rx(RX)        (column vectors, v_world = M v_obj)
 * i.e. rotate about X first, then Y, then Z, in degrees, each R right-handed
 * (Rx(a): y' = cos a y - sin a z). The viewer is on world +Z looking down -Z,
 * world +X is image right, +Y image up, and the volume's diagonal spans the
 * image width (voxels isotropic, .den has no spacing).
 * How that is made with VolPack:
 *  - vpRotate(axis, d) loads the rotation by -d in that sense (vp_linalg.c:
 *    X: y' = cos d y + sin d z), so the harness passes -angle; VP_CONCAT_LEFT
 *    (M = R * M) makes the X, Y, Z calls compose as above. The resulting
 *    VP_MODEL matrix is checked against the formula at start-up.
 *  - Depth, measured with test volumes: with a plain vpWindow (the example's
 *    near -0.5, far 0.5) the world -Z side of the volume is in front
 *    (composited first, hides what is behind it), although the man page says
 *    the viewer looks down -Z. So the VP_VIEW matrix is set to diag(1,1,-1):
 *    then world +Z is in front and X, Y keep their image directions.
 *    vpShadeTable assumes a viewer on world +Z (it uses (0,0,1) and the model
 *    matrix only), so shading then also agrees with the picture.
 *  - VolPack scales the volume by 1/max(dim) into the unit cube about the
 *    origin; the window is +-0.5*|dim|/max(dim) on all three axes.
 * --volpack-view ("view": "volpack"): the example's framing instead: angles
 * passed to vpRotate unchanged (VolPack's sign, same X, Y, Z order), no view
 * matrix (world -Z in front), window (-0.5..0.5)^3, i.e. max(dim) voxels span
 * the image and rotated corners can be clipped.
 * The PPM is written top row first (VolPack's buffer is bottom-up), so +Y is
 * up in it.
 *
 * Timing (CLOCK_MONOTONIC, per frame, N frames after K warm-up frames, one
 * thread: VolPack 1.0b3 has no threads, libvolpack links only libc and libm;
 * the process's thread count is read from /proc/self/status and reported):
 *   raw         vpShadeTable + vpRenderRawVolume (classifies every voxel
 *               every frame; shading table counted in, since cube4 shades
 *               every frame)
 *   classify    vpClassifyVolume alone (the pre-processing of the classified
 *               path: builds three run-length encoded copies of the volume)
 *   classified  vpShadeTable + vpRenderClassifiedVolume
 *
 * Output: one JSON object on stdout. Keys (stable):
 *   volume                  path of the .den file
 *   dim                     [x, y, z] voxels
 *   size                    image width = height, pixels
 *   pixel                   "rgb" or "luminance"
 *   rotate_deg              [RX, RY, RZ] as given
 *   view                    "cube4" (default) or "volpack" (--volpack-view)
 *   pixels_per_voxel        image pixels per voxel edge (the projection scale)
 *   frames, warmup          N, K
 *   max_ray_opacity         early ray termination threshold
 *   min_voxel_opacity       0.05
 *   threads                 threads in the process after the runs (1)
 *   view_axis               principal axis VolPack composited along ("x","y","z")
 *   intermediate_image      [w, h] of VolPack's sheared intermediate image
 *   voxels_per_frame        x*y*z, the voxels the raw path classifies per
 *                           frame (less what early ray termination skips)
 *   nontransparent_voxels   voxels with opacity > min_voxel_opacity (what
 *                           the classified path stores and composites)
 *   raw_ms, classify_ms, classified_ms   {"median", "min", "mean", "max"}
 *                           milliseconds per frame
 *   classified_total_ms_median   classify median + classified median
 *   raw_mvoxels_per_s       voxels_per_frame / raw median
 *   classified_mvoxels_per_s     voxels_per_frame / classified median
 *   nonzero_pixels          pixels of the raw image with any non-zero channel
 *   raw_vs_classified_max_diff   largest channel difference between the
 *                           raw and classified images (same view; sanity)
 *   image                   the --image path, or null
 */
#include <errno.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>

#include <volpack.h>

/* ---- voxel layout ---------------------------------------------------- */

typedef struct {
  unsigned short normal;   /* encoded normal (0..VP_NORM_MAX) */
  unsigned char density;   /* the .den value */
  unsigned char gradient;  /* gradient magnitude (0..VP_GRAD_MAX) */
} Voxel;

enum { F_NORMAL = 0, F_DENSITY = 1, F_GRADIENT = 2 };
enum { P_DENSITY = 0, P_GRADIENT = 1 };

/* ---- .den reader ------------------------------------------------------ */

/* A .den file: 62-byte header of 16-bit words (version, then orig_min/max/len,
 * extr_min/max/len, map_min/max/len as 3 words each, warps) and a 32-bit
 * voxel count, all in the writer's byte order (version == 1 tells which),
 * followed by x*y*z bytes, x fastest. */
#define DEN_HEADER 62

static unsigned rd16(const unsigned char *p, int big) {
  return big ? (unsigned)(p[0] << 8 | p[1]) : (unsigned)(p[1] << 8 | p[0]);
}
static uint32_t rd32(const unsigned char *p, int big) {
  return big ? (uint32_t)p[0] << 24 | (uint32_t)p[1] << 16 | (uint32_t)p[2] << 8 | p[3]
             : (uint32_t)p[3] << 24 | (uint32_t)p[2] << 16 | (uint32_t)p[1] << 8 | p[0];
}

/* Returns malloc'd densities and sets dim[3], or prints an error naming the
 * file and returns NULL. */
static unsigned char *read_den(const char *path, int dim[3]) {
  FILE *f = fopen(path, "rb");
  if (!f) {
    fprintf(stderr, "volpack_bench: cannot open %s: %s\n", path, strerror(errno));
    return NULL;
  }
  unsigned char h[DEN_HEADER];
  if (fread(h, 1, DEN_HEADER, f) != DEN_HEADER) {
    fprintf(stderr, "volpack_bench: %s: not a .den file (shorter than the %d-byte header)\n",
            path, DEN_HEADER);
    fclose(f);
    return NULL;
  }
  int big;
  if (rd16(h, 0) == 1) {
    big = 0;
  } else if (rd16(h, 1) == 1) {
    big = 1;
  } else {
    fprintf(stderr, "volpack_bench: %s: not a .den file (version word 0x%04x, expected 1)\n",
            path, rd16(h, 0));
    fclose(f);
    return NULL;
  }
  const int map_len_at = 2 + 8 * 6;  /* after version and 8 triples */
  for (int i = 0; i < 3; ++i) dim[i] = (int)rd16(h + map_len_at + 2 * i, big);
  uint32_t count = rd32(h + 58, big);
  if (dim[0] < 3 || dim[1] < 3 || dim[2] < 3 || dim[0] > VP_MAX_VOLUME_DIM ||
      dim[1] > VP_MAX_VOLUME_DIM || dim[2] > VP_MAX_VOLUME_DIM ||
      (uint64_t)dim[0] * dim[1] * dim[2] != count) {
    fprintf(stderr,
            "volpack_bench: %s: bad .den header (dimensions %d x %d x %d, voxel count %lu; "
            "need 3..%d per axis and count = product)\n",
            path, dim[0], dim[1], dim[2], (unsigned long)count, VP_MAX_VOLUME_DIM);
    fclose(f);
    return NULL;
  }
  unsigned char *data = malloc(count);
  if (!data) {
    fprintf(stderr, "volpack_bench: %s: out of memory for %lu voxels\n", path,
            (unsigned long)count);
    fclose(f);
    return NULL;
  }
  size_t got = fread(data, 1, count, f);
  fclose(f);
  if (got != count) {
    fprintf(stderr, "volpack_bench: %s: truncated (%lu of %lu voxel bytes)\n", path,
            (unsigned long)got, (unsigned long)count);
    free(data);
    return NULL;
  }
  return data;
}

/* ---- helpers ------------------------------------------------------------ */

static void die_vp(vpContext *vpc, const char *what) {
  fprintf(stderr, "volpack_bench: %s failed: %s\n", what,
          vpGetErrorString(vpGetError(vpc)));
  exit(1);
}
#define VP(call)                              \
  do {                                        \
    if ((call) != VP_OK) die_vp(vpc, #call); \
  } while (0)

static double now_ms(void) {
  struct timespec t;
  clock_gettime(CLOCK_MONOTONIC, &t);
  return t.tv_sec * 1e3 + t.tv_nsec * 1e-6;
}

typedef struct { double median, min, mean, max; } Stats;

static int cmp_double(const void *a, const void *b) {
  double x = *(const double *)a, y = *(const double *)b;
  return (x > y) - (x < y);
}

static Stats stats(double *t, int n) {
  Stats s = {0, 0, 0, 0};
  qsort(t, (size_t)n, sizeof *t, cmp_double);
  s.min = t[0];
  s.max = t[n - 1];
  s.median = n % 2 ? t[n / 2] : 0.5 * (t[n / 2 - 1] + t[n / 2]);
  for (int i = 0; i < n; ++i) s.mean += t[i];
  s.mean /= n;
  return s;
}

static int process_threads(void) {
  FILE *f = fopen("/proc/self/status", "r");
  char line[256];
  int n = -1;
  if (!f) return -1;
  while (fgets(line, sizeof line, f))
    if (sscanf(line, "Threads: %d", &n) == 1) break;
  fclose(f);
  return n;
}

/* Right-handed rotation about axis (0 x, 1 y, 2 z) by deg, column vectors. */
static void rot_std(double m[3][3], int axis, double deg) {
  double r = deg * 3.14159265358979323846 / 180.0, c = cos(r), s = sin(r);
  int a = (axis + 1) % 3, b = (axis + 2) % 3;
  memset(m, 0, 9 * sizeof(double));
  m[axis][axis] = 1;
  m[a][a] = c; m[a][b] = -s;
  m[b][a] = s; m[b][b] = c;
}

static void mul3(double out[3][3], double a[3][3], double b[3][3]) {
  double t[3][3];
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j) {
      t[i][j] = 0;
      for (int k = 0; k < 3; ++k) t[i][j] += a[i][k] * b[k][j];
    }
  memcpy(out, t, sizeof t);
}

/* Writes the image (bottom-up VolPack buffer) as a top-down binary PPM. */
static int write_ppm(const char *path, const unsigned char *img, int w, int h, int chans) {
  FILE *f = fopen(path, "wb");
  if (!f) {
    fprintf(stderr, "volpack_bench: cannot write %s: %s\n", path, strerror(errno));
    return 0;
  }
  fprintf(f, "P6\n%d %d\n255\n", w, h);
  unsigned char *row = malloc((size_t)w * 3);
  for (int y = h - 1; y >= 0; --y) {
    const unsigned char *src = img + (size_t)y * w * chans;
    for (int x = 0; x < w; ++x)
      for (int c = 0; c < 3; ++c) row[3 * x + c] = src[x * chans + (chans == 3 ? c : 0)];
    fwrite(row, 1, (size_t)w * 3, f);
  }
  free(row);
  if (fclose(f) != 0) {
    fprintf(stderr, "volpack_bench: error writing %s\n", path);
    return 0;
  }
  return 1;
}

static void usage(FILE *to) {
  fprintf(to,
          "usage: volpack_bench --den PATH [--size 256] [--rotate RX RY RZ] [--frames 20]\n"
          "                     [--warmup 3] [--image FILE.ppm] [--gray]\n"
          "                     [--max-ray-opacity 0.95] [--volpack-view]\n"
          "Times VolPack's raw and classified renderers on a .den volume; prints JSON.\n");
}

static int parse_int(const char *s, const char *opt, int lo, int hi) {
  char *end;
  long v = strtol(s, &end, 10);
  if (*s == '\0' || *end != '\0' || v < lo || v > hi) {
    fprintf(stderr, "volpack_bench: %s expects an integer in %d..%d, got '%s'\n", opt, lo, hi, s);
    exit(2);
  }
  return (int)v;
}

static double parse_double(const char *s, const char *opt) {
  char *end;
  double v = strtod(s, &end);
  if (*s == '\0' || *end != '\0' || !isfinite(v)) {
    fprintf(stderr, "volpack_bench: %s expects a number, got '%s'\n", opt, s);
    exit(2);
  }
  return v;
}

static void print_stats(const char *key, Stats s) {
  printf("  \"%s\": {\"median\": %.4f, \"min\": %.4f, \"mean\": %.4f, \"max\": %.4f},\n", key,
         s.median, s.min, s.mean, s.max);
}

static void print_json_string(const char *s) {
  putchar('"');
  for (; *s; ++s) {
    if (*s == '"' || *s == '\\') printf("\\%c", *s);
    else if ((unsigned char)*s < 0x20) printf("\\u%04x", *s);
    else putchar(*s);
  }
  putchar('"');
}

/* ---- main ---------------------------------------------------------------- */

int main(int argc, char **argv) {
  const char *den_path = NULL, *image_path = NULL;
  int size = 256, frames = 20, warmup = 3, gray = 0, volpack_view = 0;
  double rot[3] = {0, 0, 0}, max_ray_opacity = 0.95;
  const double min_voxel_opacity = 0.05;

  for (int i = 1; i < argc; ++i) {
    const char *a = argv[i];
#define NEED(n)                                                          \
  if (i + (n) >= argc) {                                                 \
    fprintf(stderr, "volpack_bench: %s needs %d value(s)\n", a, (n));   \
    return 2;                                                            \
  }
    if (!strcmp(a, "--den")) { NEED(1); den_path = argv[++i]; }
    else if (!strcmp(a, "--size")) { NEED(1); size = parse_int(argv[++i], a, 8, 4096); }
    else if (!strcmp(a, "--frames")) { NEED(1); frames = parse_int(argv[++i], a, 1, 1000000); }
    else if (!strcmp(a, "--warmup")) { NEED(1); warmup = parse_int(argv[++i], a, 0, 1000000); }
    else if (!strcmp(a, "--rotate")) {
      NEED(3);
      for (int k = 0; k < 3; ++k) rot[k] = parse_double(argv[++i], a);
    }
    else if (!strcmp(a, "--image")) { NEED(1); image_path = argv[++i]; }
    else if (!strcmp(a, "--gray")) gray = 1;
    else if (!strcmp(a, "--volpack-view")) volpack_view = 1;
    else if (!strcmp(a, "--max-ray-opacity")) {
      NEED(1);
      max_ray_opacity = parse_double(argv[++i], a);
      if (max_ray_opacity <= 0 || max_ray_opacity > 1) {
        fprintf(stderr, "volpack_bench: --max-ray-opacity must be in (0, 1]\n");
        return 2;
      }
    }
    else if (!strcmp(a, "--help") || !strcmp(a, "-h")) { usage(stdout); return 0; }
    else {
      fprintf(stderr, "volpack_bench: unknown argument '%s'\n", a);
      usage(stderr);
      return 2;
    }
#undef NEED
  }
  if (!den_path) {
    fprintf(stderr, "volpack_bench: --den PATH is required\n");
    usage(stderr);
    return 2;
  }

  int dim[3];
  unsigned char *density = read_den(den_path, dim);
  if (!density) return 1;
  const int nvox = dim[0] * dim[1] * dim[2];

  vpContext *vpc = vpCreateContext();

  /* Raw volume: normals and gradient magnitudes from the densities. */
  Voxel *voxels = malloc((size_t)nvox * sizeof(Voxel));
  if (!voxels) {
    fprintf(stderr, "volpack_bench: out of memory\n");
    return 1;
  }
  VP(vpSetVolumeSize(vpc, dim[0], dim[1], dim[2]));
  /* 3 fields; the first 2 (normal, density) are for shading, 2 classify. */
  VP(vpSetVoxelSize(vpc, sizeof(Voxel), 3, 2, 2));
  VP(vpSetVoxelField(vpc, F_NORMAL, sizeof(unsigned short), offsetof(Voxel, normal), VP_NORM_MAX));
  VP(vpSetVoxelField(vpc, F_DENSITY, 1, offsetof(Voxel, density), 255));
  VP(vpSetVoxelField(vpc, F_GRADIENT, 1, offsetof(Voxel, gradient), VP_GRAD_MAX));
  VP(vpSetRawVoxels(vpc, voxels, nvox * (int)sizeof(Voxel), sizeof(Voxel),
                    dim[0] * (int)sizeof(Voxel), dim[0] * dim[1] * (int)sizeof(Voxel)));
  VP(vpVolumeNormals(vpc, density, nvox, F_DENSITY, F_GRADIENT, F_NORMAL));

  /* Classification: opacity = density ramp * gradient ramp. */
  static float density_ramp[256], gradient_ramp[VP_GRAD_MAX + 1];
  int dx[] = {0, 24, 255};
  float dy[] = {0.0f, 1.0f, 1.0f};
  int gx[] = {0, 5, 20, VP_GRAD_MAX};
  float gy[] = {0.0f, 0.0f, 1.0f, 1.0f};
  VP(vpRamp(density_ramp, sizeof(float), 3, dx, dy));
  VP(vpRamp(gradient_ramp, sizeof(float), 4, gx, gy));
  VP(vpSetClassifierTable(vpc, P_DENSITY, F_DENSITY, density_ramp, sizeof density_ramp));
  VP(vpSetClassifierTable(vpc, P_GRADIENT, F_GRADIENT, gradient_ramp, sizeof gradient_ramp));
  VP(vpSetd(vpc, VP_MIN_VOXEL_OPACITY, min_voxel_opacity));
  long nontransparent = 0;
  for (int i = 0; i < nvox; ++i)
    if (density_ramp[voxels[i].density] * gradient_ramp[voxels[i].gradient] > min_voxel_opacity)
      ++nontransparent;

  /* Shading: lookup table indexed by the normal, one material. */
  const int chans = gray ? 1 : 3;
  float *shade_table = malloc((size_t)(VP_NORM_MAX + 1) * chans * sizeof(float));
  VP(vpSetLookupShader(vpc, chans, 1, F_NORMAL, shade_table,
                       (VP_NORM_MAX + 1) * chans * (int)sizeof(float), 0, NULL, 0));
  VP(vpSetMaterial(vpc, VP_MATERIAL0, VP_AMBIENT, VP_BOTH_SIDES, 0.18, 0.18, 0.18));
  VP(vpSetMaterial(vpc, VP_MATERIAL0, VP_DIFFUSE, VP_BOTH_SIDES, 0.35, 0.35, 0.35));
  VP(vpSetMaterial(vpc, VP_MATERIAL0, VP_SPECULAR, VP_BOTH_SIDES, 0.39, 0.39, 0.39));
  VP(vpSetMaterial(vpc, VP_MATERIAL0, VP_SHINYNESS, VP_BOTH_SIDES, 10.0, 0.0, 0.0));
  /* vpSetLight transforms the direction by the current model matrix, so it
   * is set while that matrix is still the identity: world coordinates. */
  VP(vpCurrentMatrix(vpc, VP_MODEL));
  VP(vpIdentityMatrix(vpc));
  VP(vpSetLight(vpc, VP_LIGHT0, VP_DIRECTION, 0.3, 0.3, 1.0));
  VP(vpSetLight(vpc, VP_LIGHT0, VP_COLOR, 1.0, 1.0, 1.0));
  VP(vpEnable(vpc, VP_LIGHT0, 1));
  VP(vpEnable(vpc, VP_DEPTH_CUE, 0));

  /* View: M = Rz * Ry * Rx (see the comment at the top). */
  const double sign = volpack_view ? 1.0 : -1.0;
  VP(vpSeti(vpc, VP_CONCAT_MODE, VP_CONCAT_LEFT));  /* M = R * M */
  VP(vpRotate(vpc, VP_X_AXIS, sign * rot[0]));
  VP(vpRotate(vpc, VP_Y_AXIS, sign * rot[1]));
  VP(vpRotate(vpc, VP_Z_AXIS, sign * rot[2]));
  {
    double want[3][3], r[3][3];
    rot_std(want, 0, sign * -rot[0]);
    rot_std(r, 1, sign * -rot[1]);
    mul3(want, r, want);
    rot_std(r, 2, sign * -rot[2]);
    mul3(want, r, want);
    vpMatrix4 got;
    VP(vpGetMatrix(vpc, VP_MODEL, got));
    for (int i = 0; i < 3; ++i)
      for (int j = 0; j < 3; ++j)
        if (fabs(got[i][j] - want[i][j]) > 1e-9) {
          fprintf(stderr, "volpack_bench: VolPack's model matrix differs from the intended "
                          "rotation convention (element %d,%d: %g vs %g)\n",
                  i, j, got[i][j], want[i][j]);
          return 1;
        }
  }
  if (!volpack_view) {
    vpMatrix4 flip = {{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, -1, 0}, {0, 0, 0, 1}};
    VP(vpCurrentMatrix(vpc, VP_VIEW));
    VP(vpSetMatrix(vpc, flip));
  }
  VP(vpCurrentMatrix(vpc, VP_PROJECT));
  VP(vpIdentityMatrix(vpc));
  const int maxdim = dim[0] > dim[1] ? (dim[0] > dim[2] ? dim[0] : dim[2])
                                    : (dim[1] > dim[2] ? dim[1] : dim[2]);
  const double half = volpack_view ? 0.5
                                   : 0.5 * sqrt((double)dim[0] * dim[0] + (double)dim[1] * dim[1] +
                                                (double)dim[2] * dim[2]) / maxdim;
  VP(vpWindow(vpc, VP_PARALLEL, -half, half, -half, half, -half, half));
  VP(vpCurrentMatrix(vpc, VP_MODEL));

  unsigned char *image = calloc((size_t)size * size * chans, 1);
  unsigned char *image_raw = malloc((size_t)size * size * chans);
  VP(vpSetImage(vpc, image, size, size, size * chans, gray ? VP_LUMINANCE : VP_RGB));
  VP(vpSetd(vpc, VP_MAX_RAY_OPACITY, max_ray_opacity));

  double *t = malloc((size_t)frames * sizeof(double));
  Stats raw, classify, classified;

  /* (1) raw path */
  for (int i = 0; i < warmup + frames; ++i) {
    double t0 = now_ms();
    VP(vpShadeTable(vpc));
    VP(vpRenderRawVolume(vpc));
    double t1 = now_ms();
    if (i >= warmup) t[i - warmup] = t1 - t0;
  }
  raw = stats(t, frames);
  memcpy(image_raw, image, (size_t)size * size * chans);
  int view_axis = -1, int_w = 0, int_h = 0;
  vpGeti(vpc, VP_VIEW_AXIS, &view_axis);
  vpGeti(vpc, VP_INTERMEDIATE_WIDTH, &int_w);
  vpGeti(vpc, VP_INTERMEDIATE_HEIGHT, &int_h);

  /* (2) classification (pre-processing of the classified path) */
  for (int i = 0; i < warmup + frames; ++i) {
    double t0 = now_ms();
    VP(vpClassifyVolume(vpc));
    double t1 = now_ms();
    if (i >= warmup) t[i - warmup] = t1 - t0;
  }
  classify = stats(t, frames);

  /* (3) classified path */
  for (int i = 0; i < warmup + frames; ++i) {
    double t0 = now_ms();
    VP(vpShadeTable(vpc));
    VP(vpRenderClassifiedVolume(vpc));
    double t1 = now_ms();
    if (i >= warmup) t[i - warmup] = t1 - t0;
  }
  classified = stats(t, frames);

  const int threads = process_threads();
  long nonzero = 0;
  int maxdiff = 0;
  for (long p = 0; p < (long)size * size; ++p) {
    int any = 0;
    for (int c = 0; c < chans; ++c) {
      int v = image_raw[p * chans + c], d = abs(v - image[p * chans + c]);
      any |= v != 0;
      if (d > maxdiff) maxdiff = d;
    }
    nonzero += any;
  }
  if (image_path && !write_ppm(image_path, image_raw, size, size, chans)) return 1;

  printf("{\n  \"volume\": ");
  print_json_string(den_path);
  printf(",\n  \"dim\": [%d, %d, %d],\n", dim[0], dim[1], dim[2]);
  printf("  \"size\": %d,\n  \"pixel\": \"%s\",\n", size, gray ? "luminance" : "rgb");
  printf("  \"rotate_deg\": [%g, %g, %g],\n", rot[0], rot[1], rot[2]);
  printf("  \"view\": \"%s\",\n", volpack_view ? "volpack" : "cube4");
  printf("  \"pixels_per_voxel\": %.4f,\n", size / (2.0 * half * maxdim));
  printf("  \"frames\": %d,\n  \"warmup\": %d,\n", frames, warmup);
  printf("  \"max_ray_opacity\": %g,\n  \"min_voxel_opacity\": %g,\n", max_ray_opacity,
         min_voxel_opacity);
  printf("  \"threads\": %d,\n", threads);
  printf("  \"view_axis\": \"%s\",\n",
         view_axis == VP_X_AXIS ? "x" : view_axis == VP_Y_AXIS ? "y" : view_axis == VP_Z_AXIS ? "z" : "?");
  printf("  \"intermediate_image\": [%d, %d],\n", int_w, int_h);
  printf("  \"voxels_per_frame\": %d,\n  \"nontransparent_voxels\": %ld,\n", nvox, nontransparent);
  print_stats("raw_ms", raw);
  print_stats("classify_ms", classify);
  print_stats("classified_ms", classified);
  printf("  \"classified_total_ms_median\": %.4f,\n", classify.median + classified.median);
  printf("  \"raw_mvoxels_per_s\": %.2f,\n", nvox / (raw.median * 1e3));
  printf("  \"classified_mvoxels_per_s\": %.2f,\n", nvox / (classified.median * 1e3));
  printf("  \"nonzero_pixels\": %ld,\n", nonzero);
  printf("  \"raw_vs_classified_max_diff\": %d,\n", maxdiff);
  printf("  \"image\": ");
  if (image_path) print_json_string(image_path);
  else printf("null");
  printf("\n}\n");

  vpDestroyContext(vpc);
  free(t);
  free(image);
  free(image_raw);
  free(shade_table);
  free(voxels);
  free(density);
  return 0;
}
