/* screenshot_probe PNG WIDTH HEIGHT X Y [X2 Y2]: checks that the PNG is WIDTH x HEIGHT, that pixel (X, Y) is
   bright (the particle is drawn there) and, if given, that pixel (X2, Y2) is dark (the particle is no
   longer there). Used on the screenshots the WSAD example writes. */
#define STB_IMAGE_IMPLEMENTATION
#define STBI_ONLY_PNG
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#endif
#include <stb/stb_image.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

#include <stdio.h>
#include <stdlib.h>

static int brightness(const unsigned char *image, int width, int x, int y) {
    const unsigned char *p = image + 4 * ((size_t)y * (size_t)width + (size_t)x);
    return (p[0] + p[1] + p[2]) / 3;
}

int main(int argc, char **argv) {
    int width, height, channels, x, y, ok = 1;
    unsigned char *image;
    if (argc != 6 && argc != 8) {
        fprintf(stderr, "usage: %s PNG WIDTH HEIGHT X Y [X2 Y2]\n", argv[0]);
        return 2;
    }
    image = stbi_load(argv[1], &width, &height, &channels, 4);
    if (!image) {
        fprintf(stderr, "cannot read %s: %s\n", argv[1], stbi_failure_reason());
        return 1;
    }
    if (width != atoi(argv[2]) || height != atoi(argv[3])) {
        fprintf(stderr, "%s is %dx%d, expected %sx%s\n", argv[1], width, height, argv[2], argv[3]);
        ok = 0;
    }
    x = atoi(argv[4]);
    y = atoi(argv[5]);
    if (ok && (x < 0 || y < 0 || x >= width || y >= height || brightness(image, width, x, y) < 200)) {
        fprintf(stderr, "no particle drawn at (%d, %d)\n", x, y);
        ok = 0;
    }
    if (ok && argc == 8) {
        x = atoi(argv[6]);
        y = atoi(argv[7]);
        if (x < 0 || y < 0 || x >= width || y >= height || brightness(image, width, x, y) > 50) {
            fprintf(stderr, "pixel (%d, %d) should be background\n", x, y);
            ok = 0;
        }
    }
    stbi_image_free(image);
    printf("%s: %s\n", argv[1], ok ? "particle where the state says" : "FAILED");
    return ok ? 0 : 1;
}
