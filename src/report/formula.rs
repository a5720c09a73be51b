//! The formulas and symbols of the explanations, each written once in two notations: Unicode
//! (text, Markdown's plain parts and HTML) and LaTeX math (LaTeX and Markdown's `$…$`). The
//! symbols are the chapter's (Eq. 4.1–4.17): vectors in bold in LaTeX, as the chapter prints
//! them.

/// A formula or symbol of the explanation.
#[derive(Clone, Copy, Debug, PartialEq, Eq)]
pub enum Formula {
    /// " = ".
    Equals,
    /// " + ".
    Plus,
    /// " × ".
    Times,
    /// "/ ‖·‖": a vector divided by its length.
    OverNorm,
    /// The ray's origin O.
    O,
    /// The ray's direction D.
    D,
    /// t, the ray parameter.
    T,
    /// O + tD.
    OPlusTD,
    /// P, the point shaded.
    P,
    /// N, the normal at P.
    N,
    /// The viewer's position E.
    E,
    /// O_a, the ambient colour.
    OA,
    /// O_d, the diffuse colour.
    OD,
    /// O_s, the specular colour.
    OS,
    /// n_s, the specular exponent.
    NS,
    /// O_r, the reflectivity.
    OR,
    /// V = (P − E)/‖P − E‖.
    VFromViewer,
    /// V = D.
    VIsD,
    /// V = −D.
    VIsMinusD,
    /// N·V.
    NDotV,
    /// I_a, the ambient light.
    IA,
    /// O_a I_a.
    Ambient,
    /// C_l, a light's colour.
    CL,
    /// D_l, a light's direction or a spot's axis.
    DL,
    /// γ, a spot's cone angle.
    Gamma,
    /// e, a spot's exponent.
    SpotExponent,
    /// L = (P − P_l)/‖P − P_l‖.
    LFromLight,
    /// d = ‖P − P_l‖.
    Distance,
    /// f, the falloff exponent.
    F,
    /// 1/d^f.
    FalloffFactor,
    /// L = D_l.
    LIsDl,
    /// cos ψ = D_l·L.
    CosPsi,
    /// ψ, the angle between a spot's axis and L.
    Psi,
    /// (cos ψ)^e.
    SpotFactor,
    /// I_l = C_l/d^f · (cos ψ)^e.
    IlSpot,
    /// I_l = C_l/d^f.
    IlPoint,
    /// I_l = C_l.
    IlDirectional,
    /// N·L.
    NDotL,
    /// cos θ = −N·L.
    CosTheta,
    /// O_d I_l cos θ.
    Diffuse,
    /// R = L − 2(N·L)N.
    R,
    /// cos φ = −R·V.
    CosPhi,
    /// (cos φ)^n_s.
    CosPhiPow,
    /// O_s I_l (cos φ)^n_s.
    Specular,
    /// I, the colour of Eq. 4.16.
    I,
    /// P_l, a point or spot light's position.
    PL,
    /// Q, a point on a plane.
    Q,
    /// C, a sphere's centre.
    Center,
    /// r, a sphere's radius.
    Radius,
    /// R_V = V − 2(N·V)N, the reflection ray's direction (Eq. 4.17).
    RV,
    /// O_t, the transmissivity.
    OT,
    /// η, a material's index of refraction.
    Eta,
    /// η_i, the index of the medium the ray travels in.
    EtaI,
    /// η_t, the index of the medium beyond the surface.
    EtaT,
    /// η_r = η_i/η_t.
    EtaR,
    /// cos θ_i = −N·V.
    CosThetaI,
    /// k = 1 − η_r²(1 − cos²θ_i).
    SnellK,
    /// T = η_r V + (η_r cos θ_i − √k) N, the transmitted direction.
    SnellT,
    /// w_s = w_p·max(O_r), a reflection ray's weight.
    WS,
    /// w_t = w_p·max(O_t), a transmission ray's weight.
    WT,
    /// N = (b₀N₀ + b₁N₁ + b₂N₂)/‖b₀N₀ + b₁N₁ + b₂N₂‖, a smooth triangle's shading normal.
    NSmooth,
    /// (b₀, b₁, b₂), the barycentric weights.
    Barycentric,
    /// N₀, the vertex normal at a triangle's first corner.
    N0,
    /// N₁.
    N1,
    /// N₂.
    N2,
    /// N_g, a triangle's geometric normal.
    NG,
}

impl Formula {
    /// The formula in Unicode, as the text report prints it.
    pub fn unicode(self) -> &'static str {
        use Formula::*;
        match self {
            Equals => " = ",
            Plus => " + ",
            Times => " × ",
            OverNorm => "/ ‖·‖",
            O => "O",
            D => "D",
            T => "t",
            OPlusTD => "O + tD",
            P => "P",
            N => "N",
            E => "E",
            OA => "O_a",
            OD => "O_d",
            OS => "O_s",
            NS => "n_s",
            OR => "O_r",
            VFromViewer => "V = (P − E)/‖P − E‖",
            VIsD => "V = D",
            VIsMinusD => "V = −D",
            NDotV => "N·V",
            IA => "I_a",
            Ambient => "O_a I_a",
            CL => "C_l",
            DL => "D_l",
            Gamma => "γ",
            SpotExponent => "e",
            LFromLight => "L = (P − P_l)/‖P − P_l‖",
            Distance => "d = ‖P − P_l‖",
            F => "f",
            FalloffFactor => "1/d^f",
            LIsDl => "L = D_l",
            CosPsi => "cos ψ = D_l·L",
            Psi => "ψ",
            SpotFactor => "(cos ψ)^e",
            IlSpot => "I_l = C_l/d^f · (cos ψ)^e",
            IlPoint => "I_l = C_l/d^f",
            IlDirectional => "I_l = C_l",
            NDotL => "N·L",
            CosTheta => "cos θ = −N·L",
            Diffuse => "O_d I_l cos θ",
            R => "R = L − 2(N·L)N",
            CosPhi => "cos φ = −R·V",
            CosPhiPow => "(cos φ)^n_s",
            Specular => "O_s I_l (cos φ)^n_s",
            I => "I",
            PL => "P_l",
            Q => "Q",
            Center => "C",
            Radius => "r",
            RV => "R_V = V − 2(N·V)N",
            OT => "O_t",
            Eta => "η",
            EtaI => "η_i",
            EtaT => "η_t",
            EtaR => "η_r = η_i/η_t",
            CosThetaI => "cos θ_i = −N·V",
            SnellK => "k = 1 − η_r²(1 − cos²θ_i)",
            SnellT => "T = η_r V + (η_r cos θ_i − √k) N",
            WS => "w_s = w_p·max(O_r)",
            WT => "w_t = w_p·max(O_t)",
            NSmooth => "N = (b_0 N_0 + b_1 N_1 + b_2 N_2)/‖b_0 N_0 + b_1 N_1 + b_2 N_2‖",
            Barycentric => "(b_0, b_1, b_2)",
            N0 => "N_0",
            N1 => "N_1",
            N2 => "N_2",
            NG => "N_g",
        }
    }

    /// The formula in LaTeX math mode.
    pub fn latex(self) -> &'static str {
        use Formula::*;
        match self {
            Equals => " = ",
            Plus => " + ",
            Times => " \\times ",
            OverNorm => "/\\lVert\\cdot\\rVert",
            O => "O",
            D => "\\mathbf{D}",
            T => "t",
            OPlusTD => "O + t\\mathbf{D}",
            P => "P",
            N => "\\mathbf{N}",
            E => "E",
            OA => "O_a",
            OD => "O_d",
            OS => "O_s",
            NS => "n_s",
            OR => "O_r",
            VFromViewer => "\\mathbf{V} = \\frac{P - E}{\\lVert P - E\\rVert}",
            VIsD => "\\mathbf{V} = \\mathbf{D}",
            VIsMinusD => "\\mathbf{V} = -\\mathbf{D}",
            NDotV => "\\mathbf{N}\\cdot\\mathbf{V}",
            IA => "I_a",
            Ambient => "O_a I_a",
            CL => "C_l",
            DL => "\\mathbf{D}_l",
            Gamma => "\\gamma",
            SpotExponent => "e",
            LFromLight => "\\mathbf{L} = \\frac{P - P_l}{\\lVert P - P_l\\rVert}",
            Distance => "d = \\lVert P - P_l\\rVert",
            F => "f",
            FalloffFactor => "1/d^f",
            LIsDl => "\\mathbf{L} = \\mathbf{D}_l",
            CosPsi => "\\cos\\psi = \\mathbf{D}_l\\cdot\\mathbf{L}",
            Psi => "\\psi",
            SpotFactor => "(\\cos\\psi)^e",
            IlSpot => "I_l = \\frac{C_l}{d^f}(\\cos\\psi)^e",
            IlPoint => "I_l = \\frac{C_l}{d^f}",
            IlDirectional => "I_l = C_l",
            NDotL => "\\mathbf{N}\\cdot\\mathbf{L}",
            CosTheta => "\\cos\\theta = -\\mathbf{N}\\cdot\\mathbf{L}",
            Diffuse => "O_d I_l \\cos\\theta",
            R => "\\mathbf{R} = \\mathbf{L} - 2(\\mathbf{N}\\cdot\\mathbf{L})\\mathbf{N}",
            CosPhi => "\\cos\\phi = -\\mathbf{R}\\cdot\\mathbf{V}",
            CosPhiPow => "(\\cos\\phi)^{n_s}",
            Specular => "O_s I_l (\\cos\\phi)^{n_s}",
            I => "I",
            PL => "P_l",
            Q => "Q",
            Center => "C",
            Radius => "r",
            RV => "\\mathbf{R}_V = \\mathbf{V} - 2(\\mathbf{N}\\cdot\\mathbf{V})\\mathbf{N}",
            OT => "O_t",
            Eta => "\\eta",
            EtaI => "\\eta_i",
            EtaT => "\\eta_t",
            EtaR => "\\eta_r = \\eta_i/\\eta_t",
            CosThetaI => "\\cos\\theta_i = -\\mathbf{N}\\cdot\\mathbf{V}",
            SnellK => "k = 1 - \\eta_r^2(1 - \\cos^2\\theta_i)",
            SnellT => {
                "\\mathbf{T} = \\eta_r\\mathbf{V} + (\\eta_r\\cos\\theta_i - \\sqrt{k})\\mathbf{N}"
            }
            WS => "w_s = w_p\\max(O_r)",
            WT => "w_t = w_p\\max(O_t)",
            NSmooth => {
                "\\mathbf{N} = \\frac{b_0\\mathbf{N}_0 + b_1\\mathbf{N}_1 + b_2\\mathbf{N}_2}\
                 {\\lVert b_0\\mathbf{N}_0 + b_1\\mathbf{N}_1 + b_2\\mathbf{N}_2\\rVert}"
            }
            Barycentric => "(b_0, b_1, b_2)",
            N0 => "\\mathbf{N}_0",
            N1 => "\\mathbf{N}_1",
            N2 => "\\mathbf{N}_2",
            NG => "\\mathbf{N}_g",
        }
    }
}

/// Unicode math as HTML: `X_ab` becomes X<sub>ab</sub> and `x^e` (or `x^n_s`) a superscript;
/// everything else is escaped.
pub(crate) fn unicode_to_html(s: &str) -> String {
    let mut out = String::new();
    let chars: Vec<char> = s.chars().collect();
    let mut i = 0;
    let word = |i: &mut usize| {
        let start = *i;
        while *i < chars.len() && chars[*i].is_ascii_alphanumeric() {
            *i += 1;
        }
        chars[start..*i].iter().collect::<String>()
    };
    while i < chars.len() {
        match chars[i] {
            '_' if i + 1 < chars.len() && chars[i + 1].is_ascii_alphanumeric() => {
                i += 1;
                let w = word(&mut i);
                out.push_str(&format!("<sub>{w}</sub>"));
            }
            '^' if i + 1 < chars.len() && chars[i + 1].is_ascii_alphanumeric() => {
                i += 1;
                let mut w = word(&mut i);
                if i + 1 < chars.len() && chars[i] == '_' && chars[i + 1].is_ascii_alphanumeric() {
                    i += 1;
                    w = format!("{w}<sub>{}</sub>", word(&mut i));
                }
                out.push_str(&format!("<sup>{w}</sup>"));
            }
            c => {
                push_html_escaped(&mut out, c);
                i += 1;
            }
        }
    }
    out
}

/// Appends one character escaped for HTML text and attribute values: `text::xml`'s one rule,
/// so that the HTML, the SVG diagrams and the Moodle quiz that embeds them hold no character
/// XML forbids (docs/conventions.md, "XML text").
pub(crate) fn push_html_escaped(out: &mut String, c: char) {
    crate::text::xml::push_escaped(out, c);
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn subscripts_and_superscripts_become_html_tags() {
        assert_eq!(
            unicode_to_html("I_l = C_l/d^f"),
            "I<sub>l</sub> = C<sub>l</sub>/d<sup>f</sup>"
        );
        assert_eq!(
            unicode_to_html("(cos φ)^n_s"),
            "(cos φ)<sup>n<sub>s</sub></sup>"
        );
        assert_eq!(unicode_to_html("a < b & c"), "a &lt; b &amp; c");
    }
}
