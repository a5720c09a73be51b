//! A pinhole camera: the primary ray through a point of a pixel. The image plane is one unit in
//! front of the eye, spanning tan(fov/2) up and down; x grows to the right and y downwards, as
//! in the image file. Right-handed: looking along −z with up +y, +x is to the right.

use crate::core::vector::{between, normalize};
use crate::core::{Real, Vector, V3};
use crate::geometry::Ray;
use crate::problem::Camera;

/// The camera's frame, ready to make rays.
#[derive(Clone, Copy, Debug)]
pub struct CameraRays<R: Real> {
    /// The eye, the origin of every primary ray.
    pub eye: V3<R>,
    /// The unit vector from the eye towards the look-at point.
    pub forward: V3<R>,
    /// The unit vector to the right in the image.
    pub right: V3<R>,
    /// The unit vector up in the image (at right angles to `forward`).
    pub up: V3<R>,
    /// Half the image plane's width at distance 1.
    pub half_width: R,
    /// Half the image plane's height at distance 1: tan(fov/2).
    pub half_height: R,
    /// The image's width in pixels.
    pub width: u32,
    /// The image's height in pixels.
    pub height: u32,
}

impl<R: Real> CameraRays<R> {
    /// The frame of a validated camera (eye ≠ look-at, up not along the line of sight).
    pub fn new(c: &Camera<R>) -> Self {
        let unit = |v: V3<R>| normalize::<R>(v).expect("validated camera").unit;
        // As validation computes it: look_at − eye may overflow although both are finite.
        let forward = between::<R>(c.eye, c.look_at)
            .expect("validated camera")
            .unit;
        let right = unit(forward.cross(c.up));
        let up = right.cross(forward);
        let half_height = (c.fov.to_radians() / R::TWO).tan();
        let aspect = R::from_f64(f64::from(c.width) / f64::from(c.height));
        CameraRays {
            eye: c.eye,
            forward,
            right,
            up,
            half_width: half_height * aspect,
            half_height,
            width: c.width,
            height: c.height,
        }
    }

    /// The ray from the eye through the point (x + sx, y + sy) of the image, with (sx, sy) in
    /// [0, 1)²; (0.5, 0.5) is the pixel's centre.
    #[inline]
    pub fn ray(&self, x: u32, y: u32, sx: f64, sy: f64) -> Ray<R> {
        self.ray_across(self.up_term(y, sy), x, sx)
    }

    /// The part of [`CameraRays::ray`] that depends only on the row `y` and the sample's `sy`:
    /// the image plane's up vector scaled to the point's height. A row's rays share it, so the
    /// wide engine makes it once per row and sample rather than once per ray.
    #[inline]
    pub(crate) fn up_term(&self, y: u32, sy: f64) -> V3<R> {
        let ndc_y = R::from_f64(1.0 - (f64::from(y) + sy) / f64::from(self.height) * 2.0);
        self.up * (ndc_y * self.half_height)
    }

    /// [`CameraRays::ray`] through (x + sx) across the image, at the height whose
    /// [`CameraRays::up_term`] is `up_term`: the same operations, so the same ray.
    #[inline]
    pub(crate) fn ray_across(&self, up_term: V3<R>, x: u32, sx: f64) -> Ray<R> {
        let ndc_x = R::from_f64((f64::from(x) + sx) / f64::from(self.width) * 2.0 - 1.0);
        let d = self.forward + self.right * (ndc_x * self.half_width) + up_term;
        Ray {
            origin: self.eye,
            direction: normalize::<R>(d)
                .expect("a camera ray has a direction")
                .unit,
        }
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use glam::DVec3;

    fn camera() -> CameraRays<f64> {
        CameraRays::new(&Camera {
            eye: DVec3::new(0.0, 0.0, 5.0),
            look_at: DVec3::ZERO,
            up: DVec3::Y,
            fov: 90.0,
            width: 4,
            height: 2,
        })
    }

    #[test]
    fn the_centre_of_the_image_looks_at_the_look_at_point() {
        let c = camera();
        // Between the four central pixels: x = 2, y = 1 exactly.
        let r = c.ray(1, 0, 1.0, 1.0);
        assert!((r.direction - DVec3::new(0.0, 0.0, -1.0)).length() < 1e-15);
    }

    #[test]
    fn the_top_right_corner_is_up_and_to_the_right() {
        let c = camera();
        // fov 90°: tan 45° = 1 up; aspect 2: 2 to the right. Corner (4, 0) → (2, 1, −1)/√6.
        let r = c.ray(3, 0, 1.0, 0.0);
        let expected = DVec3::new(2.0, 1.0, -1.0) / 6f64.sqrt();
        assert!(
            (r.direction - expected).length() < 1e-15,
            "{:?}",
            r.direction
        );
    }
}
