// Copyright contactlaws authors.
//
// A PNG frame read back with libpng, for the render tests.

#ifndef CONTACTLAWS_TESTS_CLI_PNG_IMAGE_H_
#define CONTACTLAWS_TESTS_CLI_PNG_IMAGE_H_

#include <png.h>

#include <string>
#include <vector>

#include <gtest/gtest.h>

namespace contactlaws::testing {

struct Image {
  int width = 0;
  int height = 0;
  std::vector<unsigned char> rgb;
  const unsigned char* at(int x, int y) const { return &rgb[3 * (y * width + x)]; }
};

inline Image ReadPng(const std::string& path) {
  png_image png = {};
  png.version = PNG_IMAGE_VERSION;
  Image image;
  if (!png_image_begin_read_from_file(&png, path.c_str())) {
    ADD_FAILURE() << path << ": " << png.message;
    return image;
  }
  png.format = PNG_FORMAT_RGB;
  image.width = static_cast<int>(png.width);
  image.height = static_cast<int>(png.height);
  image.rgb.resize(PNG_IMAGE_SIZE(png));
  png_image_finish_read(&png, nullptr, image.rgb.data(), 0, nullptr);
  return image;
}

}  // namespace contactlaws::testing

#endif  // CONTACTLAWS_TESTS_CLI_PNG_IMAGE_H_
