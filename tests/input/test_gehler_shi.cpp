// The Gehler–Shi chart reader (gehler_shi.h): hand-checked rows of the shipped
// files, the counts their provenance states (data/SOURCES.md), and a clear
// error for each kind of bad row.
#include <gmcc/input/gehler_shi.h>

#include <boost/test/unit_test.hpp>
#include <string>

using namespace gmcc;

namespace {

const std::string kTruthHeader =
    "index,image,camera,shi_real_rgb_r,shi_real_"
    "rgb_g,shi_real_rgb_b,rec2018_r,rec2018_g,"
    "rec2018_b\n";
const std::string kPatchHeader = "index,image,patch,r,g,b\n";
const std::string kTruth = kTruthHeader +
                           "1,A1,Canon1D,1,1,1,0.3,0.4,0.3\n"
                           "2,B2,Canon5D,1,1,1,1/4,1/2,1/4\n";

std::string error_of(const std::string& patches, const std::string& truth = kTruth) {
  try {
    parse_gehler_shi(patches, "p.csv", truth, "t.csv");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

std::string data(const char* name) { return std::string(GMCC_DATA_DIR) + "/" + name; }

}  // namespace

BOOST_AUTO_TEST_SUITE(gehler_shi)

BOOST_AUTO_TEST_CASE(small_file_with_a_nan_row) {
  const ChartDataset d = parse_gehler_shi(kPatchHeader +
                                              "1,A1,1,0.5,0.25,1/8\n"
                                              "1,A1,24,NaN,nan,NAN\n"
                                              "2,B2,3,0,0,0\n",
                                          "p.csv", kTruth, "t.csv");
  BOOST_TEST_REQUIRE(d.images.size() == 2u);
  BOOST_TEST(d.images[0].name == "A1");
  BOOST_TEST(d.images[1].camera == "Canon5D");
  BOOST_TEST((d.images[0].truth == Colour{Rational(3, 10), Rational(2, 5), Rational(3, 10)}));
  BOOST_TEST_REQUIRE(d.images[0].patches[0].has_value());
  BOOST_TEST((*d.images[0].patches[0] == Colour{Rational(1, 2), Rational(1, 4), Rational(1, 8)}));
  BOOST_TEST(!d.images[0].patches[23].has_value());  // the NaN row
  BOOST_TEST(d.images[1].patches[2].has_value());
  // 48 patches, 2 with a colour.
  BOOST_TEST(d.missing_patches == 46u);
}

BOOST_AUTO_TEST_CASE(bad_rows_name_file_and_line) {
  BOOST_TEST(error_of(kPatchHeader + "1,A1,1,0.5,x,1\n").find("p.csv:2: g:") == 0u);
  BOOST_TEST(error_of(kPatchHeader + "1,A1,1,0.5,-1,1\n").find("p.csv:2: channel g is negative") ==
             0u);
  BOOST_TEST(error_of(kPatchHeader + "3,C3,1,1,1,1\n") ==
             "p.csv:2: image 'C3' has no ground truth in t.csv");
  BOOST_TEST(error_of(kPatchHeader + "2,A1,1,1,1,1\n") ==
             "p.csv:2: image A1 has index 1 in t.csv, not 2");
  BOOST_TEST(error_of(kPatchHeader + "1,A1,25,1,1,1\n").find("p.csv:2: patch 25") == 0u);
  BOOST_TEST(error_of(kPatchHeader + "1,A1,0,1,1,1\n").find("p.csv:2: patch must be") == 0u);
  BOOST_TEST(error_of(kPatchHeader + "1,A1,2,NaN,NaN,NaN\n1,A1,2,1,1,1\n")
                 .find("p.csv:3: patch 2 of image A1 given twice") == 0u);
  BOOST_TEST(error_of(kPatchHeader + "1,A1,2,NaN,1,1\n").find("p.csv:2: NaN in some") == 0u);
  BOOST_TEST(error_of(kPatchHeader + "1,A1,2,1,1\n").find("p.csv:2: expected 6") == 0u);
  BOOST_TEST(error_of("index,image,patch,r,g\n").find("p.csv:1: expected the header") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader + "1,A1,Canon1D,1,1,1,0,1,1\n")
                 .find("t.csv:2: rec2018_r must be > 0") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader + "1,A1,Canon1D,1,1,1,NaN,1,1\n")
                 .find("t.csv:2: rec2018_r is NaN") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader + "2,A1,Canon1D,1,1,1,1,1,1\n")
                 .find("t.csv:2: index 2 out of order") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader + "1,A1,Nikon,1,1,1,1,1,1\n")
                 .find("t.csv:2: camera 'Nikon'") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader + "1,A1,Canon1D,1,1,1,1,1,1\n"
                                                   "2,A1,Canon1D,1,1,1,1,1,1\n")
                 .find("t.csv:3: image A1 listed twice") == 0u);
  BOOST_TEST(error_of(kPatchHeader, kTruthHeader).find("t.csv: no images") == 0u);
}

BOOST_AUTO_TEST_CASE(shipped_files) {
  const ChartDataset d = read_gehler_shi(data("gehler_shi_568_colorchecker_patch_rgb_rec2018.csv"),
                                         data("gehler_shi_568_groundtruth.csv"));
  // Counts from data/SOURCES.md: 568 images, 86 Canon 1D and 482 Canon 5D, 29
  // patches missing.
  BOOST_TEST(d.images.size() == 568u);
  std::size_t canon1d = 0, incomplete = 0;
  for (const ChartImage& image : d.images) {
    canon1d += image.camera == "Canon1D";
    std::size_t missing = 0;
    for (const auto& p : image.patches) missing += !p;
    incomplete += missing > 0;
  }
  BOOST_TEST(canon1d == 86u);
  BOOST_TEST(d.missing_patches == 29u);
  BOOST_TEST(incomplete == 17u);
  // Hand-checked rows: the first image's first patch and its ground truth, as
  // the files print them.
  const ChartImage& first = d.images.front();
  BOOST_TEST(first.name == "8D5U5524");
  BOOST_TEST((*first.patches[0] == Colour{parse_rational("0.03284811259682751"),
                                          parse_rational("0.03278548397376277"),
                                          parse_rational("0.015287214141244313")}));
  BOOST_TEST(first.truth.r == parse_rational("0.3123125267862615"));
  BOOST_TEST(first.truth.b == parse_rational("0.2647840705088546"));
}

BOOST_AUTO_TEST_SUITE_END()
