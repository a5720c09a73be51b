//! Image files: PNG (by the `image` crate) or binary PPM (P6), chosen by the extension.

use super::render::Image;

/// The image file formats `phong render` writes.
#[derive(Clone, Copy, Debug, PartialEq, Eq, clap::ValueEnum)]
// Doc comments on the variants would become help text of `--image-format`: plain comments instead.
#[allow(missing_docs)]
pub enum ImageFormat {
    // PNG, 8-bit RGB.
    Png,
    // Binary PPM (P6), 8-bit RGB.
    Ppm,
}

impl ImageFormat {
    /// The format an output path's extension names, if any.
    pub(crate) fn from_path(path: &std::path::Path) -> Option<Self> {
        let ext = path.extension()?.to_str()?.to_ascii_lowercase();
        match ext.as_str() {
            "png" => Some(ImageFormat::Png),
            "ppm" => Some(ImageFormat::Ppm),
            _ => None,
        }
    }
}

/// The file's bytes.
pub fn encode(image: &Image, format: ImageFormat) -> Vec<u8> {
    match format {
        ImageFormat::Ppm => {
            let mut out = format!("P6\n{} {}\n255\n", image.width, image.height).into_bytes();
            out.extend_from_slice(&image.rgb);
            out
        }
        ImageFormat::Png => {
            use image::ImageEncoder;
            let mut out = Vec::new();
            image::codecs::png::PngEncoder::new(&mut out)
                .write_image(
                    &image.rgb,
                    image.width,
                    image.height,
                    image::ExtendedColorType::Rgb8,
                )
                .expect("encoding an in-memory RGB image as PNG cannot fail");
            out
        }
    }
}

/// Reads a binary PPM (P6, maxval 255) back, as written by [`encode`] or by POV-Ray.
pub fn decode_ppm(bytes: &[u8]) -> Option<Image> {
    // Header: P6, width, height, maxval, each separated by whitespace (comments allowed).
    let mut fields = Vec::new();
    let mut i = 0;
    while fields.len() < 4 {
        while i < bytes.len() && bytes[i].is_ascii_whitespace() {
            i += 1;
        }
        if i < bytes.len() && bytes[i] == b'#' {
            while i < bytes.len() && bytes[i] != b'\n' {
                i += 1;
            }
            continue;
        }
        let start = i;
        while i < bytes.len() && !bytes[i].is_ascii_whitespace() {
            i += 1;
        }
        if start == i {
            return None;
        }
        fields.push(std::str::from_utf8(&bytes[start..i]).ok()?.to_owned());
    }
    if fields[0] != "P6" || fields[3] != "255" {
        return None;
    }
    let width: u32 = fields[1].parse().ok()?;
    let height: u32 = fields[2].parse().ok()?;
    let data = bytes.get(i + 1..)?;
    let n = width as usize * height as usize * 3;
    (data.len() >= n).then(|| Image {
        width,
        height,
        rgb: data[..n].to_vec(),
    })
}
