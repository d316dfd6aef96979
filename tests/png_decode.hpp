// The PNG decoder (stb_image, libstb-dev, like the writer), compiled into
// the test objects that include this and private to each (static): enough
// to compare screenshots (test_cli.cpp, test_style.cpp). Once a translation
// unit, so that the test files compiled together (Makefile, TEST_UNITY)
// define it once.
#pragma once
#define STB_IMAGE_STATIC
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#include <stb/stb_image.h>
