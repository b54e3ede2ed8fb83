// Round trips of the image writers: FITS through cfitsio, PNG through libpng.
#include <fitsio.h>
#include <gtest/gtest.h>
#include <png.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <tuple>
#include <vector>

#include "fits_writer.hpp"
#include "png_writer.hpp"

namespace fs = std::filesystem;
using namespace eoir::imageio;

namespace {

class TempDir {
 public:
  TempDir() {
    path_ = fs::temp_directory_path() / ("eoir_imageio_test_" + std::to_string(::getpid()));
    fs::create_directories(path_);
  }
  ~TempDir() {
    std::error_code ec;
    fs::remove_all(path_, ec);
  }
  std::string file(const std::string& name) const { return (path_ / name).string(); }
  std::size_t entries() const {
    std::size_t n = 0;
    for (auto it = fs::directory_iterator(path_); it != fs::directory_iterator(); ++it) ++n;
    return n;
  }

 private:
  fs::path path_;
};

struct FitsReader {
  fitsfile* f = nullptr;
  int st = 0;
  explicit FitsReader(const std::string& path) { fits_open_file(&f, path.c_str(), READONLY, &st); }
  ~FitsReader() {
    int s = 0;
    if (f) fits_close_file(f, &s);
  }
  std::string str(const char* key) {
    char* value = nullptr;
    fits_read_key_longstr(f, key, &value, nullptr, &st);
    std::string out = value ? value : "";
    if (value) fits_free_memory(value, &st);
    return out;
  }
  double dbl(const char* key, std::string* comment = nullptr) {
    double v = 0;
    char com[FLEN_COMMENT] = {0};
    fits_read_key(f, TDOUBLE, key, &v, com, &st);
    if (comment) *comment = com;
    return v;
  }
  long long lng(const char* key) {
    LONGLONG v = 0;
    fits_read_key(f, TLONGLONG, key, &v, nullptr, &st);
    return v;
  }
  bool log(const char* key) {
    int v = 0;
    fits_read_key(f, TLOGICAL, key, &v, nullptr, &st);
    return v != 0;
  }
};

// 5 x 3 test image, row 0 = top: value = 10 * row + col (+ 0.25 to test
// fractions), one NaN.
std::vector<double> test_image(int w, int h) {
  std::vector<double> v(static_cast<std::size_t>(w * h));
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) v[static_cast<std::size_t>(r * w + c)] = 10.0 * r + c + 0.25;
  return v;
}

}  // namespace

TEST(FitsWriter, Float32RoundTripWithHeaderAndUprightRows) {
  TempDir dir;
  const std::string path = dir.file("frame.fits");
  const int w = 5, h = 3;
  auto img = test_image(w, h);
  img[7] = std::numeric_limits<double>::quiet_NaN();  // row 1, col 2
  FitsHeader hdr;
  hdr.set_string("DATE-OBS", "2026-03-20T12:34:56.789", "UTC start of exposure")
      .set_string("BUNIT", "W cm-2 sr-1", "effective radiance")
      .set_double("EXPTIME", 0.0125, "[s] integration time")
      .set_integer("NINTERV", 50, "spectral intervals")
      .set_logical("SENSORON", true)
      .set_string("lowercase", "keys are upper-cased")
      .set_double("LONGKEYNAME", 1.0 / 3.0, "HIERARCH")
      .set_string("LONGSTR", std::string(150, 'x') + "END", "CONTINUE convention")
      .add_comment("written by imageio_test")
      .add_history("history line");
  FitsPointing p;
  p.ra_deg = 83.633083;
  p.dec_deg = 22.0145;
  p.crpix1 = (w + 1) / 2.0;
  p.crpix2 = (h + 1) / 2.0;
  p.cd1_1 = -1e-3;  // east to the left
  p.cd2_2 = 1e-3;
  add_tan_pointing(hdr, p);
  write_fits_image(path, img.data(), w, h, hdr);
  EXPECT_EQ(dir.entries(), 1u) << "temporary file left behind";
  EXPECT_EQ(fs::file_size(path) % 2880, 0u);

  FitsReader rd(path);
  ASSERT_EQ(rd.st, 0);
  int bitpix = 0, naxis = 0;
  long naxes[2] = {0, 0};
  fits_get_img_param(rd.f, 2, &bitpix, &naxis, naxes, &rd.st);
  EXPECT_EQ(bitpix, FLOAT_IMG);
  EXPECT_EQ(naxis, 2);
  EXPECT_EQ(naxes[0], w);
  EXPECT_EQ(naxes[1], h);
  EXPECT_EQ(rd.str("DATE-OBS"), "2026-03-20T12:34:56.789");
  EXPECT_EQ(rd.str("BUNIT"), "W cm-2 sr-1");
  std::string com;
  EXPECT_EQ(rd.dbl("EXPTIME", &com), 0.0125);
  EXPECT_EQ(com, "[s] integration time");
  EXPECT_EQ(rd.lng("NINTERV"), 50);
  EXPECT_TRUE(rd.log("SENSORON"));
  EXPECT_EQ(rd.str("LOWERCASE"), "keys are upper-cased");
  EXPECT_EQ(rd.dbl("LONGKEYNAME"), 1.0 / 3.0);  // 17 digits: exact round trip
  EXPECT_EQ(rd.str("LONGSTR"), std::string(150, 'x') + "END");
  EXPECT_EQ(rd.str("CTYPE1"), "RA---TAN");
  EXPECT_EQ(rd.str("CTYPE2"), "DEC--TAN");
  EXPECT_EQ(rd.dbl("CRVAL1"), 83.633083);
  EXPECT_EQ(rd.dbl("CRVAL2"), 22.0145);
  EXPECT_EQ(rd.dbl("CRPIX1"), 3.0);
  EXPECT_EQ(rd.dbl("CRPIX2"), 2.0);
  EXPECT_EQ(rd.dbl("CD1_1"), -1e-3);
  EXPECT_EQ(rd.str("RADESYS"), "ICRS");
  ASSERT_EQ(rd.st, 0);
  int dataok = 0, hduok = 0;
  fits_verify_chksum(rd.f, &dataok, &hduok, &rd.st);
  EXPECT_EQ(dataok, 1);
  EXPECT_EQ(hduok, 1);

  std::vector<float> back(static_cast<std::size_t>(w * h));
  int anynul = 0;
  float nulval = 0;  // 0 = no null substitution; NaN passes through
  fits_read_img(rd.f, TFLOAT, 1, w * h, &nulval, back.data(), &anynul, &rd.st);
  ASSERT_EQ(rd.st, 0);
  // FITS row j (1-based, bottom-up) = caller row h - j: the first stored row
  // is the caller's bottom row.
  for (int j = 1; j <= h; ++j) {
    for (int c = 0; c < w; ++c) {
      const double expected = img[static_cast<std::size_t>((h - j) * w + c)];
      const float got = back[static_cast<std::size_t>((j - 1) * w + c)];
      if (std::isnan(expected)) {
        EXPECT_TRUE(std::isnan(got));
      } else {
        EXPECT_EQ(got, static_cast<float>(expected)) << j << " " << c;
      }
    }
  }
  // Caller's top-left pixel (0.25) is FITS pixel (1, h) = top-left as
  // displayed.
  EXPECT_EQ(back[static_cast<std::size_t>((h - 1) * w)], 0.25f);
}

TEST(FitsWriter, Float64IsExactAndFloatInputAccepted) {
  TempDir dir;
  const int w = 4, h = 2;
  std::vector<double> img{1.0 / 3.0, 1e-300, -2.5, 1e300, 3.0e-5, 6.02214076e23, -0.0, 42.0};
  FitsWriteOptions opt;
  opt.pixel_type = FitsPixelType::Float64;
  opt.checksum = false;
  write_fits_image(dir.file("d.fits"), img.data(), w, h, FitsHeader{}, opt);
  std::vector<float> fimg{1.5f, 2.5f, 3.5f, 4.5f, 5.5f, 6.5f, 7.5f, 8.5f};
  write_fits_image(dir.file("f.fits"), fimg.data(), w, h, FitsHeader{});
  {
    FitsReader rd(dir.file("d.fits"));
    int bitpix = 0;
    fits_get_img_type(rd.f, &bitpix, &rd.st);
    EXPECT_EQ(bitpix, DOUBLE_IMG);
    std::vector<double> back(8);
    double nulval = 0;
    int anynul = 0;
    fits_read_img(rd.f, TDOUBLE, 1, 8, &nulval, back.data(), &anynul, &rd.st);
    ASSERT_EQ(rd.st, 0);
    for (int j = 0; j < h; ++j)
      for (int c = 0; c < w; ++c) EXPECT_EQ(back[j * w + c], img[(h - 1 - j) * w + c]);
    char card[FLEN_CARD];
    int st = 0;
    EXPECT_NE(fits_read_card(rd.f, const_cast<char*>("CHECKSUM"), card, &st), 0);
  }
  {
    FitsReader rd(dir.file("f.fits"));
    std::vector<float> back(8);
    float nulval = 0;
    int anynul = 0;
    fits_read_img(rd.f, TFLOAT, 1, 8, &nulval, back.data(), &anynul, &rd.st);
    ASSERT_EQ(rd.st, 0);
    EXPECT_EQ(back[0], 5.5f);  // first stored row = caller's bottom row
    EXPECT_EQ(back[4], 1.5f);
  }
}

// ADU images: unsigned integers as BITPIX 16 / 32 with BZERO 2^15 / 2^31
// (FITS 4.0 section 5.2.5), read back exactly, including both ends of the range.
TEST(FitsWriter, UnsignedIntegersWithBzero) {
  TempDir dir;
  const int w = 3, h = 2;
  const std::vector<std::uint32_t> img16{0, 1, 32767, 32768, 65534, 65535};
  const std::vector<std::uint32_t> img32{0, 65536, 2147483647u, 2147483648u, 4294967294u, 4294967295u};
  FitsWriteOptions opt;
  opt.pixel_type = FitsPixelType::UInt16;
  write_fits_image(dir.file("u16.fits"), img16.data(), w, h, FitsHeader{}, opt);
  opt.pixel_type = FitsPixelType::UInt32;
  write_fits_image(dir.file("u32.fits"), img32.data(), w, h, FitsHeader{}, opt);
  for (const auto& [name, img, bitpix, bzero] :
       {std::tuple{"u16.fits", img16, 16, 32768.0}, std::tuple{"u32.fits", img32, 32, 2147483648.0}}) {
    FitsReader rd(dir.file(name));
    int stored = 0;
    fits_get_img_type(rd.f, &stored, &rd.st);
    EXPECT_EQ(stored, bitpix) << name;
    EXPECT_EQ(rd.dbl("BZERO"), bzero) << name;
    std::vector<unsigned int> back(6);
    unsigned int nulval = 0;
    int anynul = 0;
    fits_read_img(rd.f, TUINT, 1, 6, &nulval, back.data(), &anynul, &rd.st);
    ASSERT_EQ(rd.st, 0) << name;
    for (int j = 0; j < h; ++j)
      for (int c = 0; c < w; ++c) EXPECT_EQ(back[j * w + c], img[(h - 1 - j) * w + c]) << name;
  }
  // A value past 16 bits is refused, naming it.
  opt.pixel_type = FitsPixelType::UInt16;
  EXPECT_THROW(write_fits_image(dir.file("bad.fits"), img32.data(), w, h, FitsHeader{}, opt), ImageIoError);
}

TEST(FitsWriter, AtomicReplaceAndErrors) {
  TempDir dir;
  const std::string path = dir.file("x.fits");
  std::vector<double> a(6, 1.0), b(6, 2.0);
  write_fits_image(path, a.data(), 3, 2, FitsHeader{});
  write_fits_image(path, b.data(), 3, 2, FitsHeader{});  // replaces
  {
    FitsReader rd(path);
    float v = 0, nul = 0;
    int any = 0;
    fits_read_img(rd.f, TFLOAT, 1, 1, &nul, &v, &any, &rd.st);
    EXPECT_EQ(v, 2.0f);
  }
  EXPECT_EQ(dir.entries(), 1u);
  // Failures leave the old file intact and no temporary behind.
  const auto before = fs::file_size(path);
  EXPECT_THROW(write_fits_image(path, a.data(), 0, 2, FitsHeader{}), ImageIoError);
  EXPECT_THROW(write_fits_image(dir.file("no/such/dir/x.fits"), a.data(), 3, 2, FitsHeader{}), ImageIoError);
  EXPECT_EQ(fs::file_size(path), before);
  EXPECT_EQ(dir.entries(), 1u);
  FitsHeader h;
  EXPECT_THROW(h.set_integer("NAXIS1", 3), ImageIoError);
  EXPECT_THROW(h.set_integer("bitpix", 3), ImageIoError);
  EXPECT_THROW(h.set_double("EXPTIME", std::nan("")), ImageIoError);
  EXPECT_THROW(h.set_string("", "x"), ImageIoError);
  // Names with characters cfitsio would treat as extended syntax are plain.
  const std::string odd = dir.file("frame[1](x).fits");
  write_fits_image(odd, a.data(), 3, 2, FitsHeader{});
  EXPECT_TRUE(fs::exists(odd));
}

// Saves keep the file's mode, write through symbolic links and remove
// temporaries of writers that died (issue 11 item 8, as the state files).
TEST(AtomicWrite, ModeLinksAndStaleTemporaries) {
  TempDir dir;
  const std::string path = dir.file("frame.fits");
  std::vector<double> a(6, 1.0);
  write_fits_image(path, a.data(), 3, 2, FitsHeader{});
  fs::permissions(path, fs::perms::owner_read | fs::perms::owner_write);
  write_fits_image(path, a.data(), 3, 2, FitsHeader{});
  EXPECT_EQ(fs::status(path).permissions() & fs::perms::all, fs::perms::owner_read | fs::perms::owner_write);
  // through a symbolic link: the target is replaced, the link stays
  fs::create_directory(dir.file("real"));
  write_fits_image(dir.file("real/x.fits"), a.data(), 3, 2, FitsHeader{});
  fs::create_symlink("real/x.fits", dir.file("link.fits"));
  std::vector<double> big(60, 2.0);
  write_fits_image(dir.file("link.fits"), big.data(), 6, 10, FitsHeader{});
  EXPECT_TRUE(fs::is_symlink(dir.file("link.fits")));
  {
    FitsReader rd(dir.file("real/x.fits"));
    long naxes[2] = {0, 0};
    fits_get_img_size(rd.f, 2, naxes, &rd.st);
    EXPECT_EQ(naxes[0], 6);  // the new image went to the link's target
  }
  // a temporary of a process that no longer exists is removed; others stay
  pid_t dead = ::fork();
  if (dead == 0) ::_exit(0);
  ::waitpid(dead, nullptr, 0);
  const std::string stale = path + ".tmp." + std::to_string(dead) + ".0";
  const std::string live = path + ".tmp." + std::to_string(::getppid()) + ".0";
  const std::string other = path + ".tmp.notours";
  for (const auto& f : {stale, live, other}) std::ofstream(f) << "partial";
  write_fits_image(path, a.data(), 3, 2, FitsHeader{});
  EXPECT_FALSE(fs::exists(stale));
  EXPECT_TRUE(fs::exists(live));
  EXPECT_TRUE(fs::exists(other));
}

// Issue 25, item 6: a FIFO (or, as root, /dev/null) at the target was
// replaced by a regular file; it is refused naming the path and left alone.
TEST(AtomicWrite, NonRegularTargetsAreNotReplaced) {
  TempDir dir;
  const std::string fifo = dir.file("frame.fits");
  ASSERT_EQ(::mkfifo(fifo.c_str(), 0600), 0);
  std::vector<double> a(6, 1.0);
  try {
    write_fits_image(fifo, a.data(), 3, 2, FitsHeader{});
    ADD_FAILURE() << "a FIFO was replaced";
  } catch (const ImageIoError& e) {
    EXPECT_NE(std::string(e.what()).find("cannot replace " + fifo + ": not a regular file (a FIFO)"),
              std::string::npos)
        << e.what();
  }
  EXPECT_TRUE(fs::is_fifo(fifo));
  const std::string link = dir.file("link.png");
  fs::create_symlink(fifo, link);
  const unsigned char pixels[4] = {0, 1, 2, 3};
  EXPECT_THROW(write_png_gray8(link, pixels, 2, 2), ImageIoError);
  EXPECT_TRUE(fs::is_fifo(fifo));
  EXPECT_TRUE(fs::is_symlink(link));
}

TEST(FitsWriter, ByteReproducible) {
  // No wall-clock time is stamped into the file (cfitsio's default CHECKSUM
  // comments would carry one): identical inputs, identical bytes.
  TempDir dir;
  std::vector<double> a(12, 0.5);
  FitsHeader h;
  h.set_string("DATE-OBS", "2026-01-01T00:00:00").set_double("EXPTIME", 0.0125);
  write_fits_image(dir.file("a.fits"), a.data(), 4, 3, h);
  std::this_thread::sleep_for(std::chrono::milliseconds(1100));
  write_fits_image(dir.file("b.fits"), a.data(), 4, 3, h);
  auto slurp = [](const std::string& p) {
    std::ifstream f(p, std::ios::binary);
    return std::string(std::istreambuf_iterator<char>(f), {});
  };
  EXPECT_EQ(slurp(dir.file("a.fits")), slurp(dir.file("b.fits")));
  EXPECT_NE(slurp(dir.file("a.fits")).find("EXPTIME =               0.0125 "), std::string::npos);
}

TEST(PngWriter, Gray8RoundTrip) {
  TempDir dir;
  const std::string path = dir.file("frame.png");
  const int w = 7, h = 4, stride = 9;
  std::vector<std::uint8_t> px(static_cast<std::size_t>(stride * h), 0xEE);
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c) px[static_cast<std::size_t>(r * stride + c)] = static_cast<std::uint8_t>(r * 60 + c);
  write_png_gray8(path, px.data(), w, h, stride);
  EXPECT_EQ(dir.entries(), 1u);

  png_image img;
  std::memset(&img, 0, sizeof img);
  img.version = PNG_IMAGE_VERSION;
  ASSERT_TRUE(png_image_begin_read_from_file(&img, path.c_str())) << img.message;
  EXPECT_EQ(img.width, static_cast<png_uint_32>(w));
  EXPECT_EQ(img.height, static_cast<png_uint_32>(h));
  EXPECT_EQ(img.format & PNG_FORMAT_FLAG_COLOR, 0u);
  img.format = PNG_FORMAT_GRAY;
  std::vector<std::uint8_t> back(PNG_IMAGE_SIZE(img));
  ASSERT_TRUE(png_image_finish_read(&img, nullptr, back.data(), 0, nullptr)) << img.message;
  for (int r = 0; r < h; ++r)
    for (int c = 0; c < w; ++c)
      EXPECT_EQ(back[static_cast<std::size_t>(r * w + c)], px[static_cast<std::size_t>(r * stride + c)]) << r << c;

  // Raw file check: bit depth 8, colour type 0 (grayscale) in IHDR.
  std::ifstream f(path, std::ios::binary);
  std::vector<unsigned char> head(26);
  f.read(reinterpret_cast<char*>(head.data()), 26);
  EXPECT_EQ(head[1], 'P');
  EXPECT_EQ(head[24], 8);
  EXPECT_EQ(head[25], 0);

  EXPECT_THROW(write_png_gray8(path, px.data(), 0, h), ImageIoError);
  EXPECT_THROW(write_png_gray8(path, px.data(), w, h, 3), ImageIoError);
  EXPECT_THROW(write_png_gray8(dir.file("none/x.png"), px.data(), w, h), ImageIoError);
  EXPECT_EQ(dir.entries(), 1u);
}

TEST(PngWriter, ScaleToGray8) {
  const double v[] = {-1.0, 0.0, 0.5, 1.0, 2.0, std::nan(""), 0.25};
  const auto g = scale_to_gray8(v, 7, 0.0, 1.0);
  EXPECT_EQ(g, (std::vector<std::uint8_t>{0, 0, 128, 255, 255, 0, 64}));
  const auto inv = scale_to_gray8(v, 7, 1.0, 0.0);
  EXPECT_EQ(inv[1], 255);
  EXPECT_EQ(inv[3], 0);
  const auto flat = scale_to_gray8(v, 7, 0.5, 0.5);
  EXPECT_EQ(flat[1], 0);
  EXPECT_EQ(flat[2], 255);
}
