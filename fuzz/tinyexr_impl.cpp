// tinyexr's implementation (Debian's header) compiled into the fuzz build, so the
// sanitizers and coverage see inside the OpenEXR decoder, not only around it.
#define TINYEXR_IMPLEMENTATION
#include <tinyexr.h>
