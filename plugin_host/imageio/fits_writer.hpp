// FITS image writer (host side, no engine dependency), built on cfitsio.
//
// Writes one 2-D primary image, BITPIX -32 (IEEE float32, the default) or
// -64 (float64), with caller-supplied header cards, and CHECKSUM/DATASUM,
// or a data cube of such images (FitsCubeWriter, one plane at a time).
// Pixels stream to a temporary file beside the target, a row at a time
// through cfitsio's buffers (memory does not grow with the image), and the
// finished file replaces the target atomically (AtomicReplacement: fsync,
// rename), so readers never see a partial file and a failed write leaves an
// existing target untouched and no temporary. The path is used as a plain
// file name (cfitsio's extended file-name syntax does not apply).
//
// Pixel order. The caller passes a row-major buffer, pixels[row * width +
// col], with row 0 = the TOP row of the image as displayed and col 0 = the
// left column. FITS stores rows bottom-up (pixel (1,1) is the lower-left
// corner as ds9/astropy display it), so the writer flips the rows: FITS row
// j (1-based) holds caller row height - j. The image then appears upright in
// ds9, fv and astropy/matplotlib (origin='lower'). WCS CRPIX values are in
// the FITS convention: pixel (1,1) = lower-left, pixel centres at integers;
// the image centre is ((width + 1) / 2, (height + 1) / 2).
#pragma once
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

#include "atomic_write.hpp"

namespace eoir::imageio {

// BITPIX -32 / -64; unsigned integers as BITPIX 16 / 32 with BZERO 32768 /
// 2147483648 (FITS 4.0 section 5.2.5), e.g. ADU images.
enum class FitsPixelType { Float32, Float64, UInt16, UInt32 };

// Header cards in the order they are to be written (after the mandatory
// SIMPLE/BITPIX/NAXISn/EXTEND cards, which the writer owns). Keys are
// upper-cased; keys longer than 8 characters use cfitsio's HIERARCH
// convention; string values longer than 68 characters use the CONTINUE
// long-string convention. Typical keys: DATE-OBS (ISO-8601 UTC string),
// BUNIT (e.g. 'W cm-2 sr-1' or 'electrons'), EXPTIME (s), TELESCOP,
// INSTRUME, OBJECT, and the pointing keys of add_tan_pointing().
struct FitsCard {
  enum class Kind { String, Double, Integer, Logical, Comment, History };
  Kind kind = Kind::Comment;
  std::string key;
  std::string text;  // String value, or the COMMENT/HISTORY text
  double number = 0.0;
  long long integer = 0;
  bool logical = false;
  std::string comment;  // the card's "/ comment"
};

class FitsHeader {
 public:
  // Each setter appends a card (a repeated key appends again; cfitsio
  // readers return the first). Throw ImageIoError for reserved keys
  // (SIMPLE, BITPIX, NAXIS*, EXTEND, BSCALE, BZERO, END, CHECKSUM, DATASUM,
  // COMMENT, HISTORY), empty keys, or non-finite doubles.
  FitsHeader& set_string(const std::string& key, const std::string& value, const std::string& comment = "");
  FitsHeader& set_double(const std::string& key, double value, const std::string& comment = "");
  FitsHeader& set_integer(const std::string& key, long long value, const std::string& comment = "");
  FitsHeader& set_logical(const std::string& key, bool value, const std::string& comment = "");
  FitsHeader& add_comment(const std::string& text);
  FitsHeader& add_history(const std::string& text);
  const std::vector<FitsCard>& cards() const { return cards_; }

 private:
  FitsHeader& append(FitsCard card);
  std::vector<FitsCard> cards_;
};

// Gnomonic (TAN) celestial pointing, FITS WCS paper II. Writes WCSAXES,
// CTYPE1/2 = 'RA---TAN'/'DEC--TAN', CUNIT1/2 = 'deg', CRVAL1/2, CRPIX1/2,
// the CD matrix (any scale, rotation and mirroring; pixels need not be
// square) and RADESYS.
struct FitsPointing {
  double ra_deg = 0.0;   // CRVAL1: right ascension of the reference pixel
  double dec_deg = 0.0;  // CRVAL2: declination of the reference pixel
  double crpix1 = 0.0;   // reference pixel (FITS convention, see above)
  double crpix2 = 0.0;
  // CD_ij (deg per pixel): intermediate world coordinate i (1 = toward east
  // along RA, 2 = north) per step along pixel axis j (1 = x, 2 = y up).
  double cd1_1 = 0.0, cd1_2 = 0.0, cd2_1 = 0.0, cd2_2 = 0.0;
  std::string radesys = "ICRS";
  // Data cubes: a third, linear time axis (CTYPE3 'TIME', seconds from the
  // first plane, MJDREF = its date) when time_step_s > 0.
  double time_step_s = 0.0;
  double mjdref = 0.0;
  std::string dateref;  // the same time as ISO (DATEREF), if given
};
void add_tan_pointing(FitsHeader& header, const FitsPointing& pointing);

struct FitsWriteOptions {
  FitsPixelType pixel_type = FitsPixelType::Float32;
  bool checksum = true;  // CHECKSUM / DATASUM cards (deterministic)
};

// Writes pixels (width * height values, row 0 = top, see above) to `path`
// atomically. Float32 output rounds doubles to nearest; NaN is stored as
// IEEE NaN (the FITS blank for floating images). Throws ImageIoError.
void write_fits_image(const std::string& path, const float* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options = {});
void write_fits_image(const std::string& path, const double* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options = {});
// Unsigned integer pixels (options.pixel_type UInt16 or UInt32; a value past
// the type's range throws).
void write_fits_image(const std::string& path, const std::uint32_t* pixels, std::int64_t width, std::int64_t height,
                      const FitsHeader& header, const FitsWriteOptions& options);

// A data cube: `planes` images of width x height (each row 0 = top, flipped
// as above), NAXIS3 = planes.size(), followed by an optional binary table
// extension (one row per plane, e.g. the time of each plane). Columns hold
// numbers (TFORM 1D) or strings (TFORM nA). Written atomically; CHECKSUM and
// DATASUM on both HDUs. Throws ImageIoError.
struct FitsTableColumn {
  std::string name;
  std::string unit;
  std::vector<double> numbers;       // one per row, or
  std::vector<std::string> strings;  // one per row
};
struct FitsTable {
  std::string extname;  // EXTNAME of the table HDU; empty: no table
  std::vector<FitsTableColumn> columns;
};
void write_fits_cube(const std::string& path, const std::vector<const double*>& planes, std::int64_t width,
                     std::int64_t height, const FitsHeader& header, const FitsTable& table = {},
                     const FitsWriteOptions& options = {});

// The streaming writer behind write_fits_image and write_fits_cube (one
// code path, the same bytes): open() creates the temporary file with the
// header and NAXIS3 = planes (open_image: a 2-D image, its one plane k = 0);
// write_plane(k, pixels) writes plane k (0-based, any order, width * height
// values, row 0 = top); finish(table) requires every plane, appends the
// table extension (one row per plane), writes the checksums and puts the
// file in place. Destroyed without a successful finish() (an exception, a
// failed run), the writer closes and removes the temporary file and leaves
// the target as it was. Memory: cfitsio's buffers and one row, whatever the
// cube's size. Every error throws ImageIoError naming the path.
class FitsCubeWriter {
 public:
  FitsCubeWriter();
  ~FitsCubeWriter();
  FitsCubeWriter(FitsCubeWriter&&) noexcept;
  FitsCubeWriter& operator=(FitsCubeWriter&&) noexcept;
  FitsCubeWriter(const FitsCubeWriter&) = delete;
  FitsCubeWriter& operator=(const FitsCubeWriter&) = delete;

  void open(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t planes,
            const FitsHeader& header, const FitsWriteOptions& options = {});
  void open_image(const std::string& path, std::int64_t width, std::int64_t height, const FitsHeader& header,
                  const FitsWriteOptions& options = {});
  void write_plane(std::int64_t k, const double* pixels);
  void write_plane(std::int64_t k, const float* pixels);
  void write_plane(std::int64_t k, const std::uint32_t* pixels);
  void finish(const FitsTable& table = {});
  bool is_open() const { return state_ != nullptr; }

 private:
  struct State;
  template <typename In>
  void write_plane_of(std::int64_t k, const In* pixels);
  void start(const std::string& path, std::int64_t width, std::int64_t height, std::int64_t planes, bool cube,
             const FitsHeader& header, const FitsWriteOptions& options);
  std::unique_ptr<State> state_;
};

}  // namespace eoir::imageio
