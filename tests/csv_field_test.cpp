// The bench commands' CSV fields: a configuration named "native 2x, bilinear upscale" must stay
// one field (it split into two columns before, shifting every number after it).
#include <gtest/gtest.h>

#include "app/csv_field.hpp"

namespace {

TEST(CsvField, plain_text_stays_as_it_is) {
  EXPECT_EQ(app::csvField("TAAU static after 16"), "TAAU static after 16");
  EXPECT_EQ(app::csvField(""), "");
}

TEST(CsvField, commas_quotes_and_line_breaks_are_quoted) {
  EXPECT_EQ(app::csvField("native 2x, bilinear upscale"), "\"native 2x, bilinear upscale\"");
  EXPECT_EQ(app::csvField("the \"first\" level"), "\"the \"\"first\"\" level\"");
  EXPECT_EQ(app::csvField("two\nlines"), "\"two\nlines\"");
}

}  // namespace
