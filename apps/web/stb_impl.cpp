// The stb implementations core/io/image.cpp links against. Natively they come from Debian's
// libstb; under Emscripten there is no such library, so the (Debian) headers are compiled
// here. Only PNG and Radiance HDR (environments, core/io/hdr_image.cpp) are needed.
#define STBI_ONLY_PNG
#define STBI_ONLY_HDR
#define STB_IMAGE_IMPLEMENTATION
#define STB_IMAGE_WRITE_IMPLEMENTATION
#include <stb_image.h>
#include <stb_image_write.h>
