/* Reads a FITS image back with cfitsio for the `eoir run` tests (no astropy
 * on the test machines).
 *
 * usage: fits_dump FILE [RAW_OUT]
 * Prints to stdout, one per line:
 *   checksum DATAOK HDUOK      (cfitsio fits_verify_chksum: 1 ok, 0 absent, -1 bad)
 *   size NAXIS1 NAXIS2 BITPIX
 *   card KEY<TAB>VALUE         (every keyword card; VALUE as cfitsio reads it,
 *                               strings without quotes, long strings joined)
 * With RAW_OUT, writes the pixels as native float64, in FITS order (first
 * value = FITS pixel (1,1), the lower-left corner; rows of NAXIS1 values).
 * Exit status 0, or 1 with cfitsio's message on stderr. */
#include <fitsio.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static int fail(int status, const char* what) {
  char text[FLEN_STATUS];
  fits_get_errstatus(status, text);
  fprintf(stderr, "fits_dump: %s: %s (status %d)\n", what, text, status);
  return 1;
}

int main(int argc, char** argv) {
  fitsfile* f = NULL;
  int status = 0, ncards = 0, i, bitpix = 0, naxis = 0, dataok = 0, hduok = 0;
  long naxes[2] = {0, 0};
  if (argc < 2 || argc > 3) {
    fprintf(stderr, "usage: fits_dump FILE [RAW_OUT]\n");
    return 2;
  }
  if (fits_open_image(&f, argv[1], READONLY, &status)) return fail(status, argv[1]);
  if (fits_verify_chksum(f, &dataok, &hduok, &status)) return fail(status, "checksum");
  printf("checksum %d %d\n", dataok, hduok);
  if (fits_get_img_param(f, 2, &bitpix, &naxis, naxes, &status)) return fail(status, "image parameters");
  if (naxis != 2) {
    fprintf(stderr, "fits_dump: NAXIS = %d, expected 2\n", naxis);
    return 1;
  }
  printf("size %ld %ld %d\n", naxes[0], naxes[1], bitpix);
  if (fits_get_hdrspace(f, &ncards, NULL, &status)) return fail(status, "header");
  for (i = 1; i <= ncards; ++i) {
    char key[FLEN_KEYWORD], value[FLEN_VALUE], comment[FLEN_COMMENT];
    if (fits_read_keyn(f, i, key, value, comment, &status)) return fail(status, "card");
    if (key[0] == '\0' || strcmp(key, "COMMENT") == 0 || strcmp(key, "HISTORY") == 0 || strcmp(key, "CONTINUE") == 0)
      continue;
    if (value[0] == '\'') {
      char* s = NULL;
      if (fits_read_key_longstr(f, key, &s, NULL, &status)) return fail(status, key);
      printf("card %s\t%s\n", key, s);
      fits_free_memory(s, &status);
    } else {
      printf("card %s\t%s\n", key, value);
    }
  }
  if (argc == 3) {
    const long n = naxes[0] * naxes[1];
    double* pixels = (double*)malloc((size_t)n * sizeof(double));
    long first[2] = {1, 1};
    int anynul = 0;
    FILE* out;
    if (pixels == NULL) return 1;
    if (fits_read_pix(f, TDOUBLE, first, n, NULL, pixels, &anynul, &status)) return fail(status, "pixels");
    out = fopen(argv[2], "wb");
    if (out == NULL || fwrite(pixels, sizeof(double), (size_t)n, out) != (size_t)n || fclose(out) != 0) {
      fprintf(stderr, "fits_dump: cannot write %s\n", argv[2]);
      return 1;
    }
    free(pixels);
  }
  fits_close_file(f, &status);
  return status ? fail(status, "close") : 0;
}
