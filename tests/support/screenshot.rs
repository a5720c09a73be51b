//! Reading a headless browser's screenshot, for the browser tests.

/// The number of pixels of exactly the colour `rgb` in an RGB or RGBA PNG, and of all pixels.
pub fn pixels_of(png_bytes: &[u8], rgb: [u8; 3]) -> (usize, usize) {
    let decoder = png::Decoder::new(std::io::Cursor::new(png_bytes));
    let mut reader = decoder.read_info().expect("a PNG");
    let mut buf = vec![0; reader.output_buffer_size().expect("a PNG's size")];
    let info = reader.next_frame(&mut buf).expect("a PNG frame");
    let channels = match info.color_type {
        png::ColorType::Rgb => 3,
        png::ColorType::Rgba => 4,
        other => panic!("unexpected PNG colour type {other:?}"),
    };
    let data = &buf[..info.buffer_size()];
    let total = data.len() / channels;
    let hits = data
        .chunks_exact(channels)
        .filter(|p| p[..3] == rgb)
        .count();
    (hits, total)
}
