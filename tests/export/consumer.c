/* A C program using an installed nanopush through pkg-config only (no CMake):
 *   cc consumer.c -o consumer_c $(pkg-config --cflags --libs nanopush)
 * (tests/export/run_export_test.cmake, step pkgconfig_c). Runs a scene through the C API and
 * compares every number with the CSV of `nanopush run SCENE --engine ENGINE --out REFERENCE.csv`
 * (17 significant digits: read back, the same doubles, so the comparison is exact).
 * Usage: consumer_c SCENE.toml ENGINE REFERENCE.csv */
#include <nanopush.h>

#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(nanopush_error err, const char* what) {
  char msg[512];
  nanopush_get_error(err, msg, (int)sizeof msg);
  fprintf(stderr, "consumer_c: %s: %s\n", what, msg);
  return 1;
}

int main(int argc, char** argv) {
  if (argc < 4) {
    fprintf(stderr, "usage: consumer_c SCENE.toml ENGINE REFERENCE.csv\n");
    return 2;
  }
  nanopush_error err = nanopush_new_error();
  nanopush_scene scene = nanopush_load_scene(err, argv[1]);
  if (!scene) return fail(err, "nanopush_load_scene");
  nanopush_trajectory tr = nanopush_run_scene(err, scene, argv[2], NULL, 0.0, -1.0);
  if (!tr) return fail(err, "nanopush_run_scene");
  int rows = 0;
  if (nanopush_trajectory_get_size(err, tr, &rows) != NANOPUSH_OK) return fail(err, "nanopush_trajectory_get_size");
  const int ncol = NANOPUSH_TRAJECTORY_COLUMNS;
  double* data = malloc(sizeof(double) * (size_t)ncol * (size_t)rows);
  if (!data) return 1;
  if (nanopush_trajectory_get_data(err, tr, rows, data) != NANOPUSH_OK) return fail(err, "nanopush_trajectory_get_data");
  printf("consumer_c: %d rows from engine %s\nlast row:", rows, argv[2]);
  for (int c = 0; c < ncol; ++c) printf(" %.17g", data[c + ncol * (rows - 1)]);
  printf("\n");

  FILE* ref = fopen(argv[3], "r");
  if (!ref) {
    fprintf(stderr, "consumer_c: cannot open %s\n", argv[3]);
    return 1;
  }
  char line[4096];
  if (!fgets(line, sizeof line, ref) || strncmp(line, "t,x,y,theta,vx,vy,omega,fx,fy,mf", 32) != 0) {
    fprintf(stderr, "consumer_c: unexpected CSV header in %s\n", argv[3]);
    return 1;
  }
  int nref = 0, differ = 0;
  while (fgets(line, sizeof line, ref)) {
    char* p = line;
    if (nref < rows) {
      for (int c = 0; c < ncol; ++c) {
        char* end;
        const double v = strtod(p, &end);
        if (end == p || v != data[c + ncol * nref]) {
          ++differ;
          break;
        }
        p = end + (*end == ',');
      }
    }
    ++nref;
  }
  fclose(ref);
  printf("consumer_c: reference rows %d, rows that differ %d\n", nref, differ);
  free(data);
  nanopush_delete_trajectory(&tr);
  nanopush_delete_scene(&scene);
  nanopush_delete_error(&err);
  if (nref != rows || differ != 0) {
    fprintf(stderr, "consumer_c: numbers differ from nanopush run\n");
    return 1;
  }
  printf("consumer_c: identical to nanopush run\n");
  return 0;
}
