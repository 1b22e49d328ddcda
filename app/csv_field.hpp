#pragma once
// One field of a CSV row (RFC 4180): as it is, or in double quotes (doubled inside) where it
// holds a comma, a quote or a line break, so "native 2x, bilinear upscale" stays one field.
#include <string>

namespace app {

std::string csvField(const std::string& text);

}  // namespace app
