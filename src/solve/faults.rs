//! What can stop a problem from being solved, and what would fix it, in English and Portuguese
//! (crate::text, [`crate::faults!`]): a scene given to the solver, a point the rounding cannot
//! tell from a centre, a viewer or light exactly at the point, a value that overflows the
//! precision.

use crate::{faults, messages};

faults! {
    /// Why a problem cannot be solved as written.
    pub enum SolveFault {
        /// A scene (a camera and surfaces) given to `phong solve`.
        Scene =>
            "this file is a scene (a camera and surfaces): it has no point or ray to solve",
            "este arquivo é uma cena (uma câmera e superfícies): não tem ponto nem raio a resolver";
            fix "render it with `phong render FILE -o image.png` (and explain one pixel with \
                 --explain-pixel X,Y), or add a \"ray\" to solve one ray",
                "renderize-a com `phong render FILE -o image.png` (e explique um pixel com \
                 --explain-pixel X,Y), ou acrescente um \"ray\" para resolver um raio";
        /// A sphere's hit point the precision cannot tell from its centre; `fix`: what would
        /// help in that precision.
        HitAtCentre { precision: &'static str, fix: Resolve } =>
            "the hit point cannot be told from the sphere's centre in {precision}: the radius is \
             below the rounding of the coordinates",
            "o ponto de interseção não se distingue do centro da esfera em {precision}: o raio da \
             esfera é menor que o arredondamento das coordenadas";
            fix "{fix}", "{fix}";
        /// The viewer at the point shaded.
        ViewerAtPoint =>
            "the viewer is exactly at the point being shaded, so V is undefined",
            "o observador está exatamente no ponto iluminado, e V fica indefinido";
            fix "move the viewer away from the point", "afaste o observador do ponto";
        /// The distance from the viewer to the point is not finite.
        ViewerTooFar { precision: &'static str } =>
            "the distance from the viewer to the point overflows {precision}",
            "a distância do observador ao ponto passa do alcance de {precision}";
            fix "bring the coordinates into a smaller range",
                "use coordenadas de ordem de grandeza menor";
        /// A light at the point shaded.
        LightAtPoint =>
            "the light is exactly at the point being shaded, so L = (P − P_l)/‖P − P_l‖ (Eq. \
             4.1) is undefined",
            "a fonte de luz está exatamente no ponto iluminado, e L = (P − P_l)/‖P − P_l‖ (Eq. \
             4.1) fica indefinido";
            fix "move the light or the point", "mude de lugar a fonte de luz ou o ponto";
        /// A light's quantity that overflows the precision.
        LightOverflows { what: Overflowing, precision: &'static str, fix: Smaller } =>
            "{what} overflows {precision}",
            "{what} passa do alcance de {precision}";
            fix "{fix}", "{fix}";
        /// The total colour overflows the precision.
        TotalOverflows { precision: &'static str, fix: Smaller } =>
            "the total colour overflows {precision}",
            "a cor total passa do alcance de {precision}";
            fix "{fix}", "{fix}";
    }
}

messages! {
    /// What of a light overflows: `light` is its label (`lights[1] (point)`), `distance` the
    /// distance said after it (` (d = 1e+30)`) or nothing.
    pub enum Overflowing {
        /// The distance from the light to the point.
        Distance { light: String } =>
            "the distance from {light} to the point",
            "a distância de {light} ao ponto";
        /// The falloff factor.
        Falloff { light: String, distance: String } =>
            "the falloff factor 1/d^f of {light}{distance}",
            "o termo de decaimento 1/d^f de {light}{distance}";
        /// The light arriving at the point.
        Arriving { light: String, distance: String } =>
            "the light I_l arriving from {light}{distance}",
            "a luz I_l que chega de {light}{distance}";
        /// The diffuse or specular term.
        Terms { light: String } =>
            "the diffuse or specular term of {light}",
            "o termo de reflexão difusa ou especular de {light}";
    }
}

impl Default for Overflowing {
    fn default() -> Self {
        Overflowing::Distance {
            light: String::new(),
        }
    }
}

messages! {
    /// What would let the precision tell a sphere's hit point from its centre. The rounding is
    /// relative to the coordinates (of the centre, the ray's origin and the point), so scaling
    /// the whole scene changes nothing: a larger radius, or the scene moved nearer the origin,
    /// does; in f32, f64 first.
    #[derive(Default)]
    pub enum Resolve {
        /// In f32: f64 first.
        #[default]
        Precision =>
            "use --precision f64, a larger radius, or coordinates nearer the origin",
            "use --precision f64, um raio de esfera maior, ou coordenadas mais próximas da \
             origem";
        /// In f64, the most precise there is: the radius, or where the scene is.
        Radius =>
            "give the sphere a larger radius, or move the scene nearer the origin (the sphere \
             and the ray's origin nearer (0, 0, 0)): the rounding grows with the coordinates, so \
             scaling the whole scene would not help",
            "dê à esfera um raio maior, ou desloque a cena para perto da origem (a esfera e a \
             origem do raio mais perto de (0, 0, 0)): o arredondamento cresce com as \
             coordenadas, e mudar a escala de toda a cena não ajudaria";
    }
}

messages! {
    /// What would bring an overflowing result back: f64, or smaller numbers.
    #[derive(Default)]
    pub enum Smaller {
        /// In f32: f64 first.
        #[default]
        Precision =>
            "use --precision f64, or bring the numbers into a smaller range",
            "use --precision f64, ou números de ordem de grandeza menor";
        /// In f64: smaller numbers.
        Numbers =>
            "bring the numbers (colours, distances, coordinates) into a smaller range",
            "use números (cores, distâncias, coordenadas) de ordem de grandeza menor";
    }
}

#[cfg(test)]
mod tests {
    use super::*;
    use crate::text::{Fault, Lang};

    #[test]
    fn a_hit_at_the_centre_suggests_f64_only_in_f32() {
        let f32 = SolveFault::HitAtCentre {
            precision: "f32",
            fix: Resolve::Precision,
        };
        assert!(f32.fix(Lang::En).starts_with("use --precision f64"));
        let f64 = SolveFault::HitAtCentre {
            precision: "f64",
            fix: Resolve::Radius,
        };
        assert!(!f64.fix(Lang::En).contains("--precision"));
        assert!(f64
            .fix(Lang::En)
            .starts_with("give the sphere a larger radius"));
        assert!(f64.fix(Lang::Pt).starts_with("dê à esfera um raio maior"));
    }

    #[test]
    fn an_overflowing_light_names_it_in_both_languages() {
        let f = SolveFault::LightOverflows {
            what: Overflowing::Falloff {
                light: "lights[0] (point)".into(),
                distance: " (d = 1e-30)".into(),
            },
            precision: "f32",
            fix: Smaller::Precision,
        };
        assert_eq!(
            f.what(Lang::En),
            "the falloff factor 1/d^f of lights[0] (point) (d = 1e-30) overflows f32"
        );
        assert_eq!(
            f.what(Lang::Pt),
            "o termo de decaimento 1/d^f de lights[0] (point) (d = 1e-30) passa do alcance de f32"
        );
        assert_eq!(
            f.fix(Lang::Pt),
            "use --precision f64, ou números de ordem de grandeza menor"
        );
    }
}
