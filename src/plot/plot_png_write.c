/* PNG writing for the raster plot device, through libpng's simplified API
 * (no setjmp error handling needed on the Fortran side). */
#include <png.h>
#include <stdio.h>
#include <string.h>

/* Write an 8-bit RGB image, top row first, rows packed. Returns 0 on
 * success; otherwise 1 with libpng's message copied into `message`. */
int udec_png_write_rgb(const char *path, int width, int height,
                       const unsigned char *rgb, char *message, int message_len)
{
    png_image image;
    memset(&image, 0, sizeof image);
    image.version = PNG_IMAGE_VERSION;
    image.width = (png_uint_32)width;
    image.height = (png_uint_32)height;
    image.format = PNG_FORMAT_RGB;
    if (!png_image_write_to_file(&image, path, 0, rgb, 0, NULL)) {
        if (message_len > 0) snprintf(message, (size_t)message_len, "%s", image.message);
        png_image_free(&image);
        return 1;
    }
    return 0;
}
