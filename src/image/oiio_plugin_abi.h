/* The C interface of lensrt's OpenImageIO plugin (lensrt_oiio.so, built from
 * src/oiio_plugin/). lensrt itself never links OpenImageIO: its ~260 shared
 * libraries cost every process 0.3 s and 135 MB at start. The plugin is
 * dlopen'ed (image/oiio_plugin.h) only when a file's format needs it, and
 * speaks plain C so that neither side depends on the other's C++ ABI.
 *
 * Every function but lensrt_oiio_free and lensrt_oiio_last_error returns
 * LENSRT_OIIO_OK or an error, whose one-line reason lensrt_oiio_last_error
 * gives (per thread, until that thread's next call). Buffers the plugin
 * returns are freed with lensrt_oiio_free. */
#pragma once

#include <stddef.h>

#ifdef __cplusplus
extern "C" {
#endif

/* Bumped whenever anything below changes: lensrt refuses a plugin built for
 * another version of this interface. */
#define LENSRT_OIIO_ABI_VERSION 1

enum { LENSRT_OIIO_OK = 0, LENSRT_OIIO_FAILED = 1, LENSRT_OIIO_REFUSED = 2 };

/* How a file's values relate to light: linear (floats, or a file that says
 * so), the sRGB curve (8- and 16-bit files unless they say otherwise), or
 * Cineon printing density (log DPX and Cineon files). */
enum { LENSRT_OIIO_LINEAR = 0, LENSRT_OIIO_SRGB = 1, LENSRT_OIIO_CINEON = 2 };

typedef struct {
  int width;
  int height;
  int channels;
  int encoding;        /* LENSRT_OIIO_LINEAR, _SRGB or _CINEON */
  float* pixels;       /* width*height*channels, interleaved, row 0 at the top;
                          integer files give their codes scaled to [0,1] */
  char* channel_names; /* "R,G,B,A": the file's names, comma-separated */
} lensrt_oiio_image;

/* Called with the size a file declares, before its pixels are decoded:
 * returns nonzero to go on, 0 to stop (the read then returns
 * LENSRT_OIIO_REFUSED), so an untrusted header cannot make the plugin
 * allocate what it claims. */
typedef int (*lensrt_oiio_size_check)(void* context, int width, int height, int channels);

typedef struct {
  const char* format;          /* OpenImageIO's name: "tiff", "dpx", "jpeg2000", "webp" */
  int bits;                    /* per sample: 8, 10 or 16 */
  int quality;                 /* lossy quality 1..100; 0: lossless */
  const char* color_space;     /* what the values are, for the file's tag: "sRGB", "KodakLog" */
  const char* dpx_transfer;    /* DPX transfer characteristic, e.g. "Printing density"; NULL: none */
  const char* const* metadata; /* key, value, key, value, ..., NULL: string attributes */
} lensrt_oiio_write_options;

/* LENSRT_OIIO_ABI_VERSION as the plugin was built. */
int lensrt_oiio_abi_version(void);

/* "OpenImageIO 2.4.7 (OpenColorIO 2.1.2)": what the plugin runs on. */
const char* lensrt_oiio_library_version(void);

/* A file by path, any format OpenImageIO reads (the first subimage, its top
 * MIP level, every channel). `check` may be NULL. */
int lensrt_oiio_read_file(const char* path, lensrt_oiio_size_check check, void* context,
                          lensrt_oiio_image* out);

/* Bytes in memory of the named format (OpenImageIO's name: "webp", "tiff",
 * "jpeg2000", "dpx": formats whose reader takes memory). Alpha comes as
 * stored (unassociated in PNG-like files), never premultiplied on the way. */
int lensrt_oiio_read_memory(const void* bytes, size_t size, const char* format, lensrt_oiio_size_check check,
                            void* context, lensrt_oiio_image* out);

/* Writes width x height pixels of `channels` floats (values in [0,1] map to
 * the full integer range) to the file `path` (lensrt's temporary file, renamed
 * into place once this succeeds; its extension, .jp2 or .j2k, picks JPEG
 * 2000's container). To a file, not memory: OpenImageIO 2.4 writes broken
 * TIFF directories through its in-memory output. */
int lensrt_oiio_write(const char* path, const float* pixels, int width, int height, int channels,
                      const lensrt_oiio_write_options* options);

/* OpenColorIO's display transform from the config's scene_linear role to
 * `display` and `view` (NULL or "": the config's defaults), in place on
 * `pixel_count` RGB triples. Fails when OpenImageIO has no OpenColorIO or
 * the config (the $OCIO variable) has no such display. */
int lensrt_oiio_display_transform(float* rgb, size_t pixel_count, const char* display, const char* view);

/* The config's displays and their views, "sRGB: Film, Raw; Rec709: Film",
 * for messages; "" when it has none. */
int lensrt_oiio_displays(char** text);

void lensrt_oiio_free(void* buffer);
const char* lensrt_oiio_last_error(void);

#ifdef __cplusplus
}
#endif
