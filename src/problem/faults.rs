//! What can be wrong with a problem file and what would fix it, in English and Portuguese: the
//! faults of validation ([`super::validate`]), as values (crate::text, [`crate::faults!`]).
//!
//! Numbers are written as the file writes them (`super::validate::show`: `2`, not `2.0`), so
//! they are kept as that text; a precision is its name (`f32`, `f64`), the same in every
//! language.

use std::path::PathBuf;

use super::error::Invalid;
use super::format::{LightType, SurfaceType};
use crate::text::{Lang, Message, Num, Said};
use crate::{faults, messages};

faults! {
    /// What the problem asks for: a point, a ray or a scene, and what each needs.
    pub enum TargetFault {
        /// Both a point and a ray.
        PointAndRay =>
            "the problem gives both \"point\" and \"ray\"",
            "o problema dá \"point\" e \"ray\" ao mesmo tempo";
            fix "give either a point (with its normal) or a ray with surfaces, not both",
                "dê um ponto (com sua normal) ou um raio com superfícies, não os dois";
        /// A camera with no surface.
        SceneWithoutSurfaces =>
            "missing: a scene needs at least one surface for its rays to hit",
            "ausente: uma cena precisa de pelo menos uma superfície para seus raios atingirem";
            fix "add \"surfaces\": [{{\"type\": \"sphere\", ...}}], a plane, a triangle or a mesh",
                "acrescente \"surfaces\": [{{\"type\": \"sphere\", ...}}], um plano, um triângulo \
                 ou uma malha";
        /// Surfaces with neither a camera nor a ray.
        SurfacesWithoutCamera =>
            "missing, and so is a ray (the file gives surfaces, with nothing to see them)",
            "ausente, e também o raio (o arquivo dá superfícies, sem nada que as veja)";
            fix "add \"camera\": {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": 45, \
                 \"width\": 640, \"height\": 480}} to render the scene, or a \"ray\" to solve one \
                 ray",
                "acrescente \"camera\": {{\"eye\": [x, y, z], \"look_at\": [x, y, z], \"fov\": \
                 45, \"width\": 640, \"height\": 480}} para renderizar a cena, ou um \"ray\" para \
                 resolver um raio";
        /// No point, no ray, no camera, no surface.
        NothingToShade =>
            "the problem has nothing to shade",
            "o problema não tem nada a iluminar";
            fix "give \"point\" (with \"material\", and \"position\" and \"normal\" where lights \
                 need them), \"ray\" with \"surfaces\", or a \"camera\" with \"surfaces\"",
                "dê \"point\" (com \"material\", e \"position\" e \"normal\" onde as fontes de luz \
                 precisarem), \"ray\" com \"surfaces\", ou uma \"camera\" com \"surfaces\"";
        /// A point problem that gives surfaces.
        SurfacesWithPoint =>
            "surfaces are only used by a ray problem, and this problem gives a point",
            "as superfícies só são usadas num problema de raio, e este problema dá um ponto";
            fix "remove \"surfaces\", or replace \"point\" with a \"ray\"",
                "remova \"surfaces\", ou troque \"point\" por um \"ray\"";
        /// A light at a position, and no point position.
        PositionForLight { light: LightLabel } =>
            "missing: {light} needs P for L and d (Eq. 4.1)",
            "ausente: {light} precisa de P para L e d (Eq. 4.1)";
            fix "add \"position\": [x, y, z] to \"point\"",
                "acrescente \"position\": [x, y, z] a \"point\"";
        /// A viewer, and no point position.
        PositionForViewer =>
            "missing: the viewer needs P for V = (P − E)/‖P − E‖",
            "ausente: o observador precisa de P para V = (P − E)/‖P − E‖";
            fix "add \"position\": [x, y, z] to \"point\", or remove \"viewer\"",
                "acrescente \"position\": [x, y, z] a \"point\", ou remova \"viewer\"";
        /// A light, and no normal at the point.
        NormalForLight { light: LightLabel } =>
            "missing: {light} needs N for cos θ = −N·L (Eq. 4.7)",
            "ausente: {light} precisa de N para cos θ = −N·L (Eq. 4.7)";
            fix "add \"normal\": [x, y, z] to \"point\"",
                "acrescente \"normal\": [x, y, z] a \"point\"";
        /// A ray with no surface.
        RayWithoutSurfaces =>
            "missing: a ray problem needs at least one surface for the ray to hit",
            "ausente: um problema de raio precisa de pelo menos uma superfície para o raio \
             atingir";
            fix "add \"surfaces\": [{{\"type\": \"plane\", ...}}] or a sphere",
                "acrescente \"surfaces\": [{{\"type\": \"plane\", ...}}] ou uma esfera";
    }
}

faults! {
    /// The camera: its line of sight, its up vector, its field of view and its image size.
    pub enum CameraFault {
        /// The eye is the look-at point.
        LooksAtEye =>
            "the camera looks at its own eye: no line of sight",
            "a câmera olha para o próprio olho: não há linha de visada";
            fix "give a look_at point different from eye",
                "dê um ponto `look_at` diferente de `eye`";
        /// `up` is zero or along the line of sight.
        NoUp =>
            "up is zero or along the line of sight, so the image has no up direction",
            "`up` é nulo ou está na linha de visada, e a imagem fica sem direção para cima";
            fix "give an up vector not parallel to look_at − eye, such as [0, 1, 0] or [0, 0, 1]",
                "dê um vetor `up` não paralelo a `look_at` − `eye`, como [0, 1, 0] ou [0, 0, 1]";
        /// The field of view is not in (0, 180).
        NotAFov { fov: String } =>
            "{fov} degrees is not a field of view",
            "{fov} graus não é um campo de visão";
            fix "give the vertical field of view in degrees, 0 < fov < 180 (e.g. 45)",
                "dê o campo de visão vertical em graus, 0 < fov < 180 (por exemplo 45)";
        /// A field of view whose tangent rounds to 0 in the precision.
        FovTooSmall { fov: String, precision: &'static str } =>
            "{fov} degrees is too small for {precision}",
            "{fov} graus é pequeno demais para {precision}";
            fix "give a larger field of view, or use --precision f64",
                "dê um campo de visão maior, ou use --precision f64";
        /// A field of view that rounds to 180 in the precision.
        FovNear180 { fov: String, precision: &'static str } =>
            "{fov} degrees is too close to 180 for {precision}",
            "{fov} graus é próximo demais de 180 para {precision}";
            fix "give a field of view of at most 179 degrees, or use --precision f64",
                "dê um campo de visão de até 179 graus, ou use --precision f64";
        /// The image's width is 0 or too large.
        WidthOutside { side: u32, max: u32 } =>
            "{side} pixels is outside 1 to {max}",
            "{side} pixels está fora de 1 a {max}";
            fix "give the image width in pixels, 1 to {max}",
                "dê a largura da imagem em pixels, de 1 a {max}";
        /// The image's height is 0 or too large.
        HeightOutside { side: u32, max: u32 } =>
            "{side} pixels is outside 1 to {max}",
            "{side} pixels está fora de 1 a {max}";
            fix "give the image height in pixels, 1 to {max}",
                "dê a altura da imagem em pixels, de 1 a {max}";
    }
}

faults! {
    /// A tracer's setting (given in a file's `render`, on the command line or in a sweep)
    /// that is refused, and what would fix it.
    pub enum SettingFault {
        /// A maximum level of 0.
        LevelZero { max: u32 } =>
            "0 traces nothing: the primary ray already has level 1",
            "0 não traça nada: o raio primário já tem nível 1";
            fix "give a maximum level from 1 to {max} (1 = primary rays only)",
                "dê um nível máximo de 1 a {max} (1 = só os raios primários)";
        /// A maximum level above the most.
        LevelOutside { level: u32, max: u32 } =>
            "{level} is outside 1 to {max}",
            "{level} está fora de 1 a {max}";
            fix "give a maximum level from 1 to {max}: past {max} reflections a path cannot \
                 change an 8-bit pixel unless its surfaces reflect more than 99%",
                "dê um nível máximo de 1 a {max}: depois de {max} reflexões um caminho não muda \
                 um pixel de 8 bits, a menos que suas superfícies reflitam mais de 99%";
        /// More primary rays than a render may trace; `most` samples per pixel would fit.
        TooMuchWork { width: u32, height: u32, samples: u32, work: u64, max: u64, most: u64 } =>
            "{width}×{height} pixels × {samples} samples is {work} primary rays, more than the \
             {max} (2^30) a render may trace (hours of work)",
            "{width}×{height} pixels × {samples} amostras são {work} raios primários, mais que \
             os {max} (2^30) que uma renderização pode traçar (horas de trabalho)";
            fix "give at most {most} samples per pixel at this size, or a smaller image",
                "dê até {most} amostras por pixel neste tamanho, ou uma imagem menor";
        /// More primary rays than a render may trace, even at one sample per pixel.
        ImageTooLarge { width: u32, height: u32, samples: u32, work: u64, max: u64 } =>
            "{width}×{height} pixels × {samples} samples is {work} primary rays, more than the \
             {max} (2^30) a render may trace (hours of work)",
            "{width}×{height} pixels × {samples} amostras são {work} raios primários, mais que \
             os {max} (2^30) que uma renderização pode traçar (horas de trabalho)";
            fix "give a smaller image", "dê uma imagem menor";
        /// One sample's ray tree may hold more rays than a tree may.
        TreeTooLarge { level: u32, weight: String, rays: RayCount, max: u64 } =>
            "maximum level {level} with minimum weight {weight} lets one sample's ray tree hold \
             {rays} rays (a material both reflects and transmits, so each hit can spawn two \
             rays), more than the {max} (2^20) a tree may hold",
            "o nível máximo {level} com o peso mínimo {weight} deixa a árvore de raios de uma \
             amostra ter {rays} raios (um material reflete e transmite, e cada interseção pode \
             gerar dois raios), mais que os {max} (2^20) que uma árvore pode ter";
            fix "give a maximum level of at most 20, or a larger minimum weight (e.g. 0.01), \
                 which stops the rays whose weight w = w_p·max(O) has fallen below it",
                "dê um nível máximo de até 20, ou um peso mínimo maior (por exemplo 0.01), que \
                 para os raios cujo peso w = w_p·max(O) caiu abaixo dele";
        /// An explained pixel whose samples' trees may hold more rays than an explanation may;
        /// `most` samples would fit.
        ExplanationTooLarge {
            samples: u32, level: u32, weight: String, tree: RayCount, rays: RayCount, max: u64,
            most: u64,
        } =>
            "{samples} samples of up to {tree} rays each (maximum level {level}, minimum weight \
             {weight}) let the explanation hold {rays} rays, more than the {max} (2^13) an \
             explanation may hold (each ray is solved and written out in full)",
            "{samples} amostras de até {tree} raios cada (nível máximo {level}, peso mínimo \
             {weight}) deixam a explicação ter {rays} raios, mais que os {max} (2^13) que uma \
             explicação pode ter (cada raio é resolvido e escrito por inteiro)";
            fix "give at most {most} samples per pixel (--samples), a lower maximum level \
                 (--max-level) or a larger minimum weight (--min-weight)",
                "dê até {most} amostras por pixel (--samples), um nível máximo menor \
                 (--max-level) ou um peso mínimo maior (--min-weight)";
        /// An explained pixel of which one sample's tree may hold more rays than an
        /// explanation may.
        ExplainedTreeTooLarge { level: u32, weight: String, tree: RayCount, max: u64 } =>
            "maximum level {level} with minimum weight {weight} lets one sample's ray tree hold \
             {tree} rays, more than the {max} (2^13) an explanation may hold (each ray is solved \
             and written out in full)",
            "o nível máximo {level} com o peso mínimo {weight} deixa a árvore de raios de uma \
             amostra ter {tree} raios, mais que os {max} (2^13) que uma explicação pode ter \
             (cada raio é resolvido e escrito por inteiro)";
            fix "give a lower maximum level (--max-level) or a larger minimum weight \
                 (--min-weight, e.g. 0.01), which stops the rays whose weight w = w_p·max(O) has \
                 fallen below it",
                "dê um nível máximo menor (--max-level) ou um peso mínimo maior (--min-weight, \
                 por exemplo 0.01), que para os raios cujo peso w = w_p·max(O) caiu abaixo dele";
        /// A minimum weight that is negative or not finite.
        NotAWeight { weight: String } =>
            "{weight} is not a weight",
            "{weight} não é um peso";
            fix "give a minimum weight ≥ 0 (0 traces every reflection up to the maximum level)",
                "dê um peso mínimo ≥ 0 (0 traça todas as reflexões até o nível máximo)";
        /// Samples per pixel outside 1 to the most.
        SamplesOutside { samples: u32, max: u32 } =>
            "{samples} samples per pixel is outside 1 to {max}",
            "{samples} amostras por pixel está fora de 1 a {max}";
            fix "give 1 to {max} samples per pixel",
                "dê de 1 a {max} amostras por pixel";
    }
}

impl SettingFault {
    /// The error of the setting named `field` (`render.samples` in a file, `samples` among a
    /// command line's overrides).
    pub(crate) fn at(self, field: impl Into<String>) -> Invalid {
        Invalid::of(field, self)
    }
}

faults! {
    /// A light: how many, its cone, its falloff.
    pub enum LightFault {
        /// More lights than a problem may have.
        TooMany { count: usize, max: usize } =>
            "{count} lights are more than the {max} a problem may have",
            "{count} fontes de luz são mais que as {max} que um problema pode ter";
            fix "give at most {max} lights", "dê até {max} fontes de luz";
        /// A spot's angle outside [0°, 90°].
        AngleOutside { angle: String } =>
            "{angle}° is outside [0°, 90°]",
            "{angle}° está fora de [0°, 90°]";
            fix "γ is the angle between the cone's axis and its side, 0 ≤ γ ≤ 90 degrees \
                 (Eq. 4.4)",
                "γ é o ângulo entre o eixo do cone e sua geratriz, 0 ≤ γ ≤ 90 graus (Eq. 4.4)";
        /// A spot's exponent below 0.
        NegativeExponent { exponent: String } =>
            "{exponent} is negative",
            "{exponent} é negativo";
            fix "the spot exponent e of cos(ψ)^e (Eq. 4.4) must be ≥ 0, e.g. 0, 1 or 2",
                "o expoente e do spot em cos(ψ)^e (Eq. 4.4) deve ser ≥ 0, por exemplo 0, 1 ou 2";
        /// A falloff other than 0, 1 or 2.
        NotAFalloff { falloff: String } =>
            "{falloff} is not a falloff exponent",
            "{falloff} não é um fator de decaimento";
            fix "use 0 (no falloff), 1 (linear) or 2 (quadratic), Eq. 4.3",
                "use 0 (sem decaimento), 1 (linear) ou 2 (quadrático), Eq. 4.3";
    }
}

faults! {
    /// A field of a light or a surface that its type does not take, or needs and lacks.
    pub enum KindFault {
        /// A field the kind does not take; `takes` lists those it does, quoted.
        NotTaken { kind: Kind, extra: String, takes: String } =>
            "{kind} has no \"{extra}\"",
            "{kind} não tem \"{extra}\"";
            fix "remove it; {kind} takes {takes}",
                "remova-o; {kind} aceita {takes}";
        /// A field the kind needs.
        Missing { kind: Kind, name: String, purpose: Purpose } =>
            "missing: {kind} needs \"{name}\"{purpose}",
            "ausente: {kind} precisa de \"{name}\"{purpose}";
            fix "add \"{name}\"", "acrescente \"{name}\"";
    }
}

faults! {
    /// A surface: its size, its shape, and how many triangles a scene holds.
    pub enum SurfaceFault {
        /// More surfaces (a mesh's triangles each counted) than a scene may hold.
        TooMany { max: usize } =>
            "the scene has more than {max} surfaces (a mesh's triangles each count)",
            "a cena tem mais de {max} superfícies (cada triângulo de uma malha conta)";
            fix "give at most 1,000,000 surfaces and triangles in all",
                "dê até 1000000 superfícies e triângulos ao todo";
        /// A mesh whose triangles take the scene past the most surfaces.
        MeshTooLarge { path: PathBuf, triangles: usize, max: usize } =>
            "{path}: its {triangles} triangles take the scene past {max} surfaces",
            "{path}: seus {triangles} triângulos levam a cena além de {max} superfícies";
            fix "give at most 1,000,000 surfaces and triangles in all",
                "dê até 1000000 superfícies e triângulos ao todo";
        /// A mesh's triangles cannot be held in memory.
        MeshOutOfMemory { size: Bytes } =>
            "out of memory: this needs about {size}",
            "memória insuficiente: isto precisa de cerca de {size}";
            fix "give a smaller mesh, or free memory", "dê uma malha menor, ou libere memória";
        /// A radius > 0 that rounds to 0 in the precision.
        RadiusRoundsToZero { radius: String, precision: &'static str } =>
            "{radius} is too small for {precision}: it rounds to 0",
            "{radius} é pequeno demais para {precision}: é arredondado para 0";
            fix "use --precision f64, or scale the problem",
                "use --precision f64, ou mude a escala do problema";
        /// A radius beyond what the ray–sphere test can square in f64
        /// (`geometry::max_coordinate`).
        RadiusTooLarge { radius: String, max: Num, precision: &'static str } =>
            "{radius} is too large for a sphere's radius in {precision}: the ray–sphere test \
             squares the radius plus the distance from the ray's origin, which would overflow",
            "{radius} é grande demais para o raio de uma esfera em {precision}: o teste de \
             interseção com a esfera eleva ao quadrado o raio somado à distância da origem do \
             raio, o que estouraria";
            fix "give a radius of at most {max} (scale the scene down)",
                "dê um raio de até {max} (reduza a escala da cena)";
        /// The same in f32, where f64 is a way out.
        RadiusTooLargeF32 { radius: String, max: Num } =>
            "{radius} is too large for a sphere's radius in f32: the ray–sphere test squares \
             the radius plus the distance from the ray's origin, which would overflow",
            "{radius} é grande demais para o raio de uma esfera em f32: o teste de interseção \
             com a esfera eleva ao quadrado o raio somado à distância da origem do raio, o que \
             estouraria";
            fix "give a radius of at most {max} (scale the scene down), or use --precision f64",
                "dê um raio de até {max} (reduza a escala da cena), ou use --precision f64";
        /// A radius ≤ 0.
        NotARadius { radius: String } =>
            "{radius} is not a radius",
            "{radius} não é um raio";
            fix "give the sphere a radius > 0", "dê à esfera um raio > 0";
        /// A triangle whose corners lie on one line.
        Degenerate { precision: &'static str } =>
            "the triangle is degenerate in {precision}: its corners lie on one line, so it has \
             no area and no normal",
            "o triângulo é degenerado em {precision}: seus vértices estão numa reta, e ele não \
             tem área nem normal";
            fix "give three corners that are not on one line",
                "dê três vértices que não estejam numa reta";
        /// A triangle's coordinate beyond what the ray–triangle test can multiply in f64
        /// (`geometry::max_coordinate`).
        CornerTooLarge { value: String, max: Num, precision: &'static str } =>
            "{value} is too large for a triangle's corner in {precision}: the ray–triangle test \
             multiplies up to three coordinates, which would overflow",
            "{value} é grande demais para um vértice de triângulo em {precision}: o teste de \
             interseção raio–triângulo multiplica até três coordenadas, o que estouraria";
            fix "give coordinates within ±{max} (scale the scene down)",
                "dê coordenadas dentro de ±{max} (reduza a escala da cena)";
        /// The same in f32, where f64 is a way out.
        CornerTooLargeF32 { value: String, max: Num } =>
            "{value} is too large for a triangle's corner in f32: the ray–triangle test \
             multiplies up to three coordinates, which would overflow",
            "{value} é grande demais para um vértice de triângulo em f32: o teste de interseção \
             raio–triângulo multiplica até três coordenadas, o que estouraria";
            fix "give coordinates within ±{max} (scale the scene down), or use --precision f64",
                "dê coordenadas dentro de ±{max} (reduza a escala da cena), ou use --precision \
                 f64";
    }
}

faults! {
    /// A material: its name, its exponent, its reflectivity, its transmission, its
    /// coefficients, and the colours the question's terms need.
    pub enum MaterialFault {
        /// A name that no material has, and the file defines none.
        NoSuchMaterial { name: String } =>
            "there is no material named \"{name}\"",
            "não há material chamado \"{name}\"";
            fix "define it under \"materials\", or write the material in place",
                "defina-o em \"materials\", ou escreva o material em vez do nome";
        /// A name that no material has; `known` lists the names defined, quoted.
        NoSuchMaterialOf { name: String, known: String } =>
            "there is no material named \"{name}\"",
            "não há material chamado \"{name}\"";
            fix "use one of {known}, or define it under \"materials\"",
                "use um de {known}, ou defina-o em \"materials\"";
        /// n_s < 0.
        NegativeShininess { shininess: String } =>
            "{shininess} is negative",
            "{shininess} é negativo";
            fix "the specular exponent n_s (Eq. 4.9) must be ≥ 0",
                "o expoente de reflexão especular n_s (Eq. 4.9) deve ser ≥ 0";
        /// `"reflectivity": "specular"` without a specular colour.
        ReflectivityWithoutSpecular =>
            "is \"specular\" but the material has no specular colour",
            "é \"specular\", mas o material não tem cor especular";
            fix "give \"specular\", or give the reflectivity as [r, g, b]",
                "dê \"specular\", ou dê a reflexividade como [r, g, b]";
        /// O_t without η.
        IorMissing =>
            "is missing, and the material has a transmissivity",
            "falta, e o material tem uma transmissividade";
            fix "give the index of refraction of the material's inside, e.g. \"ior\": 1.5 for \
                 glass (the outside's is 1); Snell's law needs it to bend the transmitted ray",
                "dê o índice de refração do interior do material, por exemplo \"ior\": 1.5 para \
                 o vidro (o do exterior é 1); a lei de Snell precisa dele para desviar o raio \
                 transmitido";
        /// η without O_t.
        TransmissivityMissing =>
            "is missing, and the material has an index of refraction",
            "falta, e o material tem um índice de refração";
            fix "give the transmissivity O_t as [r, g, b] (e.g. [0.9, 0.9, 0.9]), or remove \
                 \"ior\": without O_t no ray is transmitted",
                "dê a transmissividade O_t como [r, g, b] (por exemplo [0.9, 0.9, 0.9]), ou \
                 retire \"ior\": sem O_t nenhum raio é transmitido";
        /// η ≤ 0.
        IorNotPositive { ior: String } =>
            "{ior} is not a positive number",
            "{ior} não é um número positivo";
            fix "an index of refraction is > 0: give one from 0.001 to 1000 (1 for air, 1.33 for \
                 water, 1.5 for glass)",
                "um índice de refração é > 0: dê um de 0.001 a 1000 (1 para o ar, 1.33 para a \
                 água, 1.5 para o vidro)";
        /// η > 0 outside the range Snell's law is computed in.
        IorOutside { ior: String, min: String, max: String } =>
            "{ior} is outside {min} to {max}",
            "{ior} está fora de {min} a {max}";
            fix "give an index of refraction from {min} to {max} (1 for air, 1.33 for water, 1.5 \
                 for glass, 2.42 for diamond); outside it, η_r² in Snell's law \
                 k = 1 − η_r²(1 − cos²θ_i) can overflow",
                "dê um índice de refração de {min} a {max} (1 para o ar, 1.33 para a água, 1.5 \
                 para o vidro, 2.42 para o diamante); fora dessa faixa, η_r² na lei de Snell \
                 k = 1 − η_r²(1 − cos²θ_i) pode estourar";
        /// A coefficient k of `{"k": k, "color": …}` outside [0, 1].
        CoefficientOutside { k: String } =>
            "{k} is outside [0, 1]",
            "{k} está fora de [0, 1]";
            fix "the chapter's coefficients k_a, k_d, k_s lie in [0, 1] (Eq. 4.5, 4.7, 4.9); \
                 give the product as one colour [r, g, b] if you mean something else",
                "os coeficientes k_a, k_d, k_s do capítulo estão em [0, 1] (Eq. 4.5, 4.7, 4.9); \
                 dê o produto como uma só cor [r, g, b] se quer outra coisa";
        /// O_a missing where there is an ambient light.
        AmbientMissing =>
            "missing: the ambient term O_a I_a (Eq. 4.6) needs it, since the problem has an \
             ambient light",
            "ausente: o termo de luz ambiente O_a I_a (Eq. 4.6) precisa dele, pois o problema \
             tem uma luz ambiente";
            fix "add \"ambient\": [r, g, b] (or {{\"k\": k, \"color\": [r, g, b]}}); [0, 0, 0] \
                 if the surface reflects no ambient light",
                "acrescente \"ambient\": [r, g, b] (ou {{\"k\": k, \"color\": [r, g, b]}}); \
                 [0, 0, 0] se a superfície não reflete luz ambiente";
        /// O_d missing where a light needs it.
        DiffuseMissing { light: LightLabel } =>
            "missing: the diffuse term O_d I_l cos θ (Eq. 4.8) of {light} needs it",
            "ausente: o termo de reflexão difusa O_d I_l cos θ (Eq. 4.8) de {light} precisa \
             dele";
            fix "add \"diffuse\": [r, g, b] (or {{\"k\": k, \"color\": [r, g, b]}}); [0, 0, 0] \
                 for no diffuse reflection",
                "acrescente \"diffuse\": [r, g, b] (ou {{\"k\": k, \"color\": [r, g, b]}}); \
                 [0, 0, 0] para nenhuma reflexão difusa";
        /// O_s missing where a light and a viewer need it.
        SpecularMissing { light: LightLabel } =>
            "missing: the specular term O_s I_l (cos φ)^n_s (Eq. 4.10) of {light} needs it, \
             since the problem has a viewer",
            "ausente: o termo de reflexão especular O_s I_l (cos φ)^n_s (Eq. 4.10) de {light} \
             precisa dele, pois o problema tem um observador";
            fix "add \"specular\": [r, g, b] (or {{\"k\": k, \"color\": [r, g, b]}}); [0, 0, 0] \
                 for a matte surface",
                "acrescente \"specular\": [r, g, b] (ou {{\"k\": k, \"color\": [r, g, b]}}); \
                 [0, 0, 0] para uma superfície fosca";
        /// n_s missing where a light and a viewer need it.
        ShininessMissing { light: LightLabel } =>
            "missing: the specular term (Eq. 4.10) of {light} needs the exponent n_s",
            "ausente: o termo de reflexão especular (Eq. 4.10) de {light} precisa do expoente \
             n_s";
            fix "add \"shininess\": n_s (a number ≥ 0)",
                "acrescente \"shininess\": n_s (um número ≥ 0)";
    }
}

faults! {
    /// A colour with a negative component, written `[r, g, b]` as the file writes it.
    pub enum ColourFault {
        /// A light's colour C_l.
        Light { r: String, g: String, b: String } =>
            "a light's colour has a negative component: [{r}, {g}, {b}]",
            "a cor de uma fonte de luz tem um componente negativo: [{r}, {g}, {b}]";
            fix "colour components must be ≥ 0", "os componentes de uma cor devem ser ≥ 0";
        /// A material's colour.
        Material { r: String, g: String, b: String } =>
            "a material colour has a negative component: [{r}, {g}, {b}]",
            "uma cor de material tem um componente negativo: [{r}, {g}, {b}]";
            fix "colour components must be ≥ 0", "os componentes de uma cor devem ser ≥ 0";
        /// The background colour.
        Background { r: String, g: String, b: String } =>
            "the background colour has a negative component: [{r}, {g}, {b}]",
            "a cor de fundo tem um componente negativo: [{r}, {g}, {b}]";
            fix "colour components must be ≥ 0", "os componentes de uma cor devem ser ≥ 0";
    }
}

faults! {
    /// A number that is not finite in the precision, a direction that is no direction, or a
    /// coordinate beyond what the intersection tests can multiply.
    pub enum NumberFault {
        /// Not finite in f64 (or beyond f64 in any precision).
        NotFinite { value: String, precision: &'static str } =>
            "{value} is not a finite {precision} number",
            "{value} não é um número finito em {precision}";
            fix "use a finite number", "use um número finito";
        /// Not finite in f32, where f64 may hold it.
        NotFiniteF32 { value: String } =>
            "{value} is not a finite f32 number",
            "{value} não é um número finito em f32";
            fix "use a number within ±3.4e38, or --precision f64",
                "use um número dentro de ±3.4e38, ou --precision f64";
        /// A vector whose length overflows the precision.
        TooLong { vector: DirectionOf, precision: &'static str } =>
            "{vector} is too long for {precision}: its length overflows",
            "{vector} tem comprimento grande demais para {precision}: seu comprimento estoura";
            fix "give a shorter vector in the same direction (only the direction is used)",
                "dê um vetor mais curto na mesma direção (só a direção é usada)";
        /// A vector whose length overflows f32.
        TooLongF32 { vector: DirectionOf } =>
            "{vector} is too long for f32: its length overflows",
            "{vector} tem comprimento grande demais para f32: seu comprimento estoura";
            fix "give a shorter vector in the same direction (only the direction is used), or \
                 use --precision f64",
                "dê um vetor mais curto na mesma direção (só a direção é usada), ou use \
                 --precision f64";
        /// The zero vector where a direction is needed.
        ZeroVector { vector: DirectionOf, precision: &'static str } =>
            "{vector} is the zero vector (in {precision}), which has no direction",
            "{vector} é o vetor nulo (em {precision}), que não tem direção";
            fix "give a non-zero vector", "dê um vetor não nulo";
        /// A number the file writes with a digit other than 0 that is below the smallest f64
        /// above 0, so that serde_json read it as 0 (`1e-330`): what the error its 0 gave says
        /// (`what`, `fix`), after why (`problem::written`).
        ReadAsZero { written: String, what: Said, fix: Said } =>
            "{written} is too small to represent (the smallest number above 0 is about \
             4.9e-324), so it is read as 0: {what}",
            "{written} é pequeno demais para ser representado (o menor número acima de 0 é \
             cerca de 4.9e-324), e é lido como 0: {what}";
            fix "{fix}", "{fix}";
        /// A coordinate of a point the intersection tests take beyond what they can multiply
        /// in f64 (`geometry::max_coordinate`).
        CoordinateTooLarge { value: String, of: PointOf, max: Num, precision: &'static str } =>
            "{value} is too large for {of} in {precision}: the ray–surface tests multiply \
             coordinates taken relative to the ray's origin, which would overflow",
            "{value} é grande demais para {of} em {precision}: os testes de interseção \
             multiplicam coordenadas tomadas em relação à origem do raio, o que estouraria";
            fix "give coordinates within ±{max} (scale the scene down)",
                "dê coordenadas dentro de ±{max} (reduza a escala da cena)";
        /// The same in f32, where f64 is a way out.
        CoordinateTooLargeF32 { value: String, of: PointOf, max: Num } =>
            "{value} is too large for {of} in f32: the ray–surface tests multiply coordinates \
             taken relative to the ray's origin, which would overflow",
            "{value} é grande demais para {of} em f32: os testes de interseção multiplicam \
             coordenadas tomadas em relação à origem do raio, o que estouraria";
            fix "give coordinates within ±{max} (scale the scene down), or use --precision f64",
                "dê coordenadas dentro de ±{max} (reduza a escala da cena), ou use --precision \
                 f64";
    }
}

messages! {
    /// A point the intersection tests take the coordinates of, as a message names it.
    #[derive(Default, Copy)]
    pub enum PointOf {
        /// O of a ray problem's ray.
        #[default]
        RayOrigin => "the ray's origin", "a origem do raio";
        /// The camera's eye E.
        Eye => "the camera's eye", "o olho da câmera";
        /// The point the camera looks at.
        LookAt => "the point the camera looks at", "o ponto para onde a câmera olha";
        /// A sphere's centre C.
        SphereCentre => "a sphere's centre", "o centro de uma esfera";
        /// A plane's point Q.
        PlanePoint => "a plane's point", "o ponto de um plano";
    }
}

messages! {
    /// A vector used as a direction, as a message names it.
    #[derive(Default, Copy)]
    pub enum DirectionOf {
        /// N at a point.
        #[default]
        Normal => "the normal N", "a normal N";
        /// D of a ray.
        RayDirection => "the ray's direction", "a direção do raio";
        /// D_l of a directional light.
        LightDirection => "the light's direction D_l", "a direção D_l da fonte de luz";
        /// D_l of a spot light.
        ConeAxis => "the cone's axis D_l", "o eixo D_l do cone";
        /// A plane's normal.
        PlaneNormal => "the plane's normal", "a normal do plano";
    }
}

/// What a missing field gives, after its name (`: it gives P_l, for L and d (Eq. 4.1)`), as
/// the format's tables say it (`super::field_purpose`); nothing for a field they do not
/// describe.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Purpose(Option<super::syntax::Purpose>);

impl Purpose {
    /// What the field `name` of a light or a surface gives.
    pub(crate) fn of(name: &str) -> Purpose {
        Purpose(super::field_purpose(name))
    }
}

impl Message for Purpose {
    fn text(&self, lang: Lang) -> String {
        match (&self.0, lang) {
            (None, _) => String::new(),
            (Some(p), Lang::En) => format!(": it gives {}", p.text(lang)),
            (Some(p), Lang::Pt) => format!(": dá {}", p.text(lang)),
        }
    }
}

/// A light named by its index in the file's `lights` and its kind: `lights[1] (point)`,
/// `lights[1] (pontual)`.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct LightLabel {
    /// Its index in the file's `lights`.
    pub index: usize,
    /// Its kind.
    pub kind: LightType,
}

impl LightLabel {
    /// The light at `index` whose kind the file writes `word` (`"point"`); `None` for a word
    /// that is no light's kind.
    pub(crate) fn of(index: usize, word: &str) -> Option<LightLabel> {
        let kind = *LightType::ALL.iter().find(|k| k.name() == word)?;
        Some(LightLabel { index, kind })
    }
}

impl Default for LightLabel {
    fn default() -> Self {
        LightLabel {
            index: 0,
            kind: LightType::Point,
        }
    }
}

impl Message for LightLabel {
    fn text(&self, lang: Lang) -> String {
        format!("lights[{}] ({})", self.index, self.kind.word(lang))
    }
}

/// The kind of a light or a surface, with its article, as a message names it: `a point light`,
/// `uma luz pontual`, `a plane`, `um plano`. (English writes `a ambient light`, as it always
/// has.)
#[derive(Clone, Copy, Debug, PartialEq)]
pub enum Kind {
    /// A light of this kind.
    Light(LightType),
    /// A surface of this kind.
    Surface(SurfaceType),
}

impl Default for Kind {
    fn default() -> Self {
        Kind::Light(LightType::Point)
    }
}

impl Message for Kind {
    fn text(&self, lang: Lang) -> String {
        match (*self, lang) {
            (Kind::Light(k), Lang::En) => format!("a {} light", k.name()),
            (Kind::Light(k), Lang::Pt) => format!("uma luz {}", k.word(lang)),
            (Kind::Surface(s), Lang::En) => format!("a {}", s.name()),
            (Kind::Surface(s), Lang::Pt) => match s {
                SurfaceType::Plane => "um plano",
                SurfaceType::Sphere => "uma esfera",
                SurfaceType::Triangle => "um triângulo",
                SurfaceType::Mesh => "uma malha",
            }
            .to_owned(),
        }
    }
}

/// How many rays a tree may hold, saturated at `u64::MAX` (written `more than 2^63`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct RayCount(pub u64);

impl Message for RayCount {
    fn text(&self, lang: Lang) -> String {
        match (self.0, lang) {
            (u64::MAX, Lang::En) => "more than 2^63".to_owned(),
            (u64::MAX, Lang::Pt) => "mais de 2^63".to_owned(),
            (n, _) => n.to_string(),
        }
    }
}

/// A size in memory, as an out-of-memory message writes it: `2.1 GB`, `512 MB` (at least
/// `1 MB`).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct Bytes(pub usize);

impl Message for Bytes {
    fn text(&self, _: Lang) -> String {
        let b = self.0 as f64;
        if b >= 1e9 {
            format!("{:.1} GB", b / 1e9)
        } else {
            format!("{:.0} MB", (b / 1e6).max(1.0))
        }
    }
}

#[cfg(test)]
mod tests {

    use super::*;
    use crate::text::Fault;

    #[test]
    fn a_light_label_names_the_kind_in_the_messages_language() {
        let l = LightLabel::of(1, "point").unwrap();
        assert_eq!(l.text(Lang::En), "lights[1] (point)");
        assert_eq!(l.text(Lang::Pt), "lights[1] (pontual)");
        let f = TargetFault::NormalForLight {
            light: LightLabel::of(2, "directional").unwrap(),
        };
        assert_eq!(
            f.what(Lang::En),
            "missing: lights[2] (directional) needs N for cos θ = −N·L (Eq. 4.7)"
        );
        assert_eq!(
            f.what(Lang::Pt),
            "ausente: lights[2] (direcional) precisa de N para cos θ = −N·L (Eq. 4.7)"
        );
        assert!(LightLabel::of(0, "lamp").is_none());
    }

    #[test]
    fn a_kind_has_its_article_in_each_language() {
        let cases = [
            (
                Kind::Light(LightType::Ambient),
                "a ambient light",
                "uma luz ambiente",
            ),
            (Kind::Light(LightType::Spot), "a spot light", "uma luz spot"),
            (Kind::Surface(SurfaceType::Plane), "a plane", "um plano"),
            (Kind::Surface(SurfaceType::Sphere), "a sphere", "uma esfera"),
            (
                Kind::Surface(SurfaceType::Triangle),
                "a triangle",
                "um triângulo",
            ),
            (Kind::Surface(SurfaceType::Mesh), "a mesh", "uma malha"),
        ];
        for (kind, en, pt) in cases {
            assert_eq!(kind.text(Lang::En), en);
            assert_eq!(kind.text(Lang::Pt), pt);
        }
    }

    #[test]
    fn every_purpose_is_the_format_tables_in_english() {
        // The English of each field a kind takes is the table's (`phong schema` says the same).
        let names = LightType::ALL
            .iter()
            .flat_map(|k| k.fields())
            .chain(SurfaceType::ALL.iter().flat_map(|k| k.fields()));
        for name in names {
            let p = Purpose::of(name);
            assert!(p.0.is_some(), "{name}");
            assert!(p.text(Lang::En).starts_with(": it gives "), "{name}");
            assert!(p.text(Lang::Pt).starts_with(": dá "), "{name}");
        }
    }

    #[test]
    fn a_ray_count_past_u64_is_said_in_each_language() {
        assert_eq!(RayCount(5).text(Lang::Pt), "5");
        assert_eq!(RayCount(u64::MAX).text(Lang::En), "more than 2^63");
        assert_eq!(RayCount(u64::MAX).text(Lang::Pt), "mais de 2^63");
        assert_eq!(Bytes(2_100_000_000).text(Lang::En), "2.1 GB");
        assert_eq!(Bytes(10).text(Lang::Pt), "1 MB");
    }
}
