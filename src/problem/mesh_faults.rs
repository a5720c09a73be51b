//! What can be wrong with a mesh's OBJ file and what would fix it, as values ([`MeshFault`]),
//! the line it is on ([`MeshError`]) and the mesh's path before it ([`MeshAt`]).

use std::fmt;
use std::path::PathBuf;

use super::reading::{Cause, Limit, ReadFix};
use crate::faults;
use crate::text::{Echo, Fault, Lang, Num, Show};

/// " (or use --precision f64)" after a fix, in precision f32 only (where f64 is a way out).
#[derive(Clone, Copy, Debug, Default, PartialEq)]
pub struct OrF64(pub bool);

impl Show for OrF64 {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (self.0, lang) {
            (false, _) => Ok(()),
            (true, Lang::En) => f.write_str(" (or use --precision f64)"),
            (true, Lang::Pt) => f.write_str(" (ou use --precision f64)"),
        }
    }
}

/// The object a triangle is in, when the file names it (`o name`): ` (object "name")`.
#[derive(Clone, Debug, Default, PartialEq)]
pub struct Object(pub Option<String>);

impl Show for Object {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        match (&self.0, lang) {
            (None, _) => Ok(()),
            (Some(name), Lang::En) => write!(f, " (object \"{name}\")"),
            (Some(name), Lang::Pt) => write!(f, " (objeto \"{name}\")"),
        }
    }
}

/// What the OBJ reader (`tobj`) said, in the message's language.
#[derive(Clone, Copy, Debug, PartialEq)]
pub struct ObjError(pub tobj::LoadError);

impl Default for ObjError {
    fn default() -> Self {
        ObjError(tobj::LoadError::GenericFailure)
    }
}

impl Show for ObjError {
    fn show(&self, lang: Lang, f: &mut fmt::Formatter<'_>) -> fmt::Result {
        use tobj::LoadError::*;
        if lang == Lang::En {
            return fmt::Display::fmt(&self.0, f);
        }
        f.write_str(match self.0 {
            OpenFileFailed => "falha ao abrir o arquivo",
            ReadError => "erro de leitura",
            UnrecognizedCharacter => "caractere não reconhecido",
            PositionParseError => "erro ao ler uma posição",
            ScalingByZeroError => "escala (w) zero",
            ColorParseError => "erro ao ler uma cor (componentes demais ou de menos)",
            NormalParseError => "erro ao ler uma normal",
            TexcoordParseError => "erro ao ler uma coordenada de textura",
            FaceParseError => "erro ao ler uma face",
            MaterialParseError => "erro ao ler um material",
            InvalidObjectName => "nome de objeto inválido",
            InvalidPolygon => "polígono inválido",
            FaceVertexOutOfBounds => "índice de vértice de face fora do intervalo",
            FaceTexCoordOutOfBounds => "índice de coordenada de textura de face fora do intervalo",
            FaceNormalOutOfBounds => "índice de normal de face fora do intervalo",
            FaceColorOutOfBounds => "índice de cor de vértice de face fora do intervalo",
            InvalidLoadOptionConfig => "opções de leitura incompatíveis",
            GenericFailure => "falha genérica",
        })
    }
}

faults! {
    /// What is wrong with a mesh's OBJ file.
    pub enum MeshFault {
        /// A `v` line that is not three numbers.
        VertexNotXyz { v: Echo } =>
            "the vertex \"{v}\" is not `v x y z` (three numbers)",
            "o vértice \"{v}\" não é `v x y z` (três números)";
            fix "write each vertex as `v x y z`", "escreva cada vértice como `v x y z`";
        /// A vertex not finite in the precision.
        VertexNotFinite { v: Echo, precision: String, or_f64: OrF64 } =>
            "the vertex \"{v}\" is not finite in {precision}",
            "o vértice \"{v}\" não é finito em {precision}";
            fix "give finite coordinates{or_f64}", "dê coordenadas finitas{or_f64}";
        /// A `vn` line that is not three numbers.
        NormalNotXyz { v: Echo } =>
            "the vertex normal \"{v}\" is not `vn x y z` (three numbers)",
            "a normal de vértice \"{v}\" não é `vn x y z` (três números)";
            fix "write each vertex normal as `vn x y z`",
                "escreva cada normal de vértice como `vn x y z`";
        /// A vertex normal not finite in the precision.
        NormalNotFinite { v: Echo, precision: String } =>
            "the vertex normal \"{v}\" is not finite in {precision}",
            "a normal de vértice \"{v}\" não é finita em {precision}";
            fix "give each `vn` three finite numbers, a direction such as `vn 0 1 0`",
                "dê a cada `vn` três números finitos, uma direção como `vn 0 1 0`";
        /// A vertex normal of length zero in the precision.
        NormalZero { v: Echo, precision: String, or_f64: OrF64 } =>
            "the vertex normal \"{v}\" has length zero in {precision}, so it has no direction",
            "a normal de vértice \"{v}\" tem comprimento zero em {precision}, então não tem \
             direção";
            fix "give each `vn` a direction of nonzero length{or_f64}, or remove the mesh's `vn` \
                 lines and the faces' `//n` parts for flat shading",
                "dê a cada `vn` uma direção de comprimento não nulo{or_f64}, ou remova as linhas \
                 `vn` da malha e as partes `//n` das faces para um sombreamento plano";
        /// An `l` line.
        LineElement { v: Echo } =>
            "\"{v}\" is a line element, which has no surface to hit",
            "\"{v}\" é um elemento de linha, que não tem superfície a atingir";
            fix "remove the `l` lines (faces are `f i j k`)",
                "remova as linhas `l` (as faces são `f i j k`)";
        /// A face of fewer than three vertices.
        FewVertices { v: Echo, n: usize } =>
            "the face \"{v}\" has {n} vertices, and a face needs at least 3",
            "a face \"{v}\" tem {n} vértices, e uma face precisa de pelo menos 3";
            fix "give each face three or more vertices (`f i j k`)",
                "dê a cada face três ou mais vértices (`f i j k`)";
        /// A face's normal index that no `vn` line before it gives.
        NormalIndex { v: Echo, word: String, r: String, known: i64 } =>
            "the face \"{v}\" refers to vertex normal {word} (in {r}), and {known} vertex normals \
             come before it",
            "a face \"{v}\" se refere à normal de vértice {word} (em {r}), e {known} normais de \
             vértice vêm antes dela";
            fix "correct the face's normal indices (the third number of `v/vt/vn`; 1 is the \
                 first `vn` line)",
                "corrija os índices de normais da face (o terceiro número de `v/vt/vn`; 1 é a \
                 primeira linha `vn`)";
        /// A face with normals at some of its corners only.
        PartialNormals { v: Echo, given: usize, n: usize } =>
            "the face \"{v}\" gives vertex normals for {given} of its {n} vertices; a face is \
             smooth with a normal at every corner, or flat with none",
            "a face \"{v}\" dá normais de vértice para {given} de seus {n} vértices; uma face é \
             suave com uma normal em cada vértice, ou plana sem nenhuma";
            fix "give every vertex of the face a normal (`v//vn`), or none (`v`)",
                "dê uma normal a cada vértice da face (`v//vn`), ou a nenhum (`v`)";
        /// A face's vertex index that no `v` line before it gives.
        VertexIndex { v: Echo, r: String, vertices: usize } =>
            "the face \"{v}\" refers to vertex {r}, and {vertices} vertices come before it",
            "a face \"{v}\" se refere ao vértice {r}, e {vertices} vértices vêm antes dela";
            fix "correct the face's vertex indices (1 is the first vertex)",
                "corrija os índices de vértices da face (1 é o primeiro vértice)";
        /// A line whose first word is none of OBJ's statements (a vertex written `V`, a
        /// misspelt keyword): read past, it would shift every vertex index after it.
        UnknownStatement { v: Echo, word: Echo } =>
            "the line \"{v}\" is not an OBJ statement: `{word}` is none of OBJ's keywords (`v`, \
             `vt`, `vn`, `f`, `g`, `o`, `s`, `usemtl`, `mtllib`, …), which are lower case",
            "a linha \"{v}\" não é uma instrução OBJ: `{word}` não é nenhuma das palavras-chave \
             do OBJ (`v`, `vt`, `vn`, `f`, `g`, `o`, `s`, `usemtl`, `mtllib`, …), que são \
             minúsculas";
            fix "write the line as OBJ does (`v x y z` for a vertex), make it a comment with `#`, \
                 or remove it",
                "escreva a linha como o OBJ a escreve (`v x y z` para um vértice), torne-a um \
                 comentário com `#` ou remova-a";
        /// More triangles than a scene holds.
        TooManyTriangles { max: usize } =>
            "the mesh has more than {max} triangles",
            "a malha tem mais de {max} triângulos";
            fix "give a mesh of at most {max} triangles (simplify it, for example with \
                 Blender's Decimate modifier)",
                "dê uma malha de até {max} triângulos (simplifique-a, por exemplo com o \
                 modificador Decimate do Blender)";
        /// A file that cannot be read, and its fix.
        Unreadable { cause: Cause, fix: ReadFix } =>
            "cannot be read: {cause}", "não pode ser lido: {cause}";
            fix "{fix}", "{fix}";
        /// What the OBJ reader refused.
        NotObj { error: ObjError } =>
            "is not a valid Wavefront OBJ file: {error}",
            "não é um arquivo Wavefront OBJ válido: {error}";
            fix "give an OBJ file with `v x y z` vertices and `f i j k` faces",
                "dê um arquivo OBJ com vértices `v x y z` e faces `f i j k`";
        /// Memory refused for the triangles.
        OutOfMemory { memory: Limit } =>
            "{memory}", "{memory}";
            fix "give a smaller mesh, or free memory", "dê uma malha menor, ou libere memória";
        /// A face's vertex the reader does not have.
        MissingVertex { index: usize } =>
            "a face refers to vertex {index} which does not exist",
            "uma face se refere ao vértice {index}, que não existe";
            fix "correct the face's vertex indices", "corrija os índices de vértices da face";
        /// A corner not finite in the precision.
        CornerNotFinite { index: usize, precision: String, or_f64: OrF64 } =>
            "vertex {index} is not finite in {precision}",
            "o vértice {index} não é finito em {precision}";
            fix "give finite coordinates{or_f64}", "dê coordenadas finitas{or_f64}";
        /// A corner beyond what the ray–triangle test can multiply in the precision
        /// (`geometry::max_coordinate`).
        CornerTooLarge { index: usize, precision: String, max: Num, or_f64: OrF64 } =>
            "vertex {index} is too large for a triangle in {precision}: the ray–triangle test \
             multiplies up to three coordinates, which would overflow",
            "o vértice {index} é grande demais para um triângulo em {precision}: o teste de \
             interseção raio–triângulo multiplica até três coordenadas, o que estouraria";
            fix "give coordinates within ±{max} (scale the mesh down){or_f64}",
                "dê coordenadas dentro de ±{max} (reduza a escala da malha){or_f64}";
        /// A triangle without area.
        Degenerate { k: usize, object: Object, precision: String } =>
            "the face's triangle {k}{object} is degenerate in {precision}: its corners lie on one \
             line",
            "o triângulo {k}{object} da face é degenerado em {precision}: seus vértices estão \
             numa reta";
            fix "remove the degenerate face from the OBJ file",
                "remova a face degenerada do arquivo OBJ";
        /// No face at all.
        NoFaces =>
            "has no faces", "não tem faces";
            fix "give an OBJ file with at least one face (`f i j k`)",
                "dê um arquivo OBJ com pelo menos uma face (`f i j k`)";
    }
}

/// Why a mesh could not be used: the fault, and the line of the OBJ file it is on.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshError {
    /// The line of the OBJ file, from 1, when the fault is on one.
    pub line: Option<usize>,
    /// What is wrong and what would fix it.
    pub fault: MeshFault,
}

impl MeshError {
    /// `fault`, on no line in particular.
    pub fn of(fault: MeshFault) -> Self {
        MeshError { line: None, fault }
    }

    /// `fault` on line `line`.
    pub fn at_line(line: usize, fault: MeshFault) -> Self {
        MeshError {
            line: Some(line),
            fault,
        }
    }

    /// What is wrong, in English.
    #[cfg(test)]
    pub fn message(&self) -> String {
        self.what(Lang::En)
    }

    /// The error in the mesh at `path`, as the problem's validation reports it.
    pub fn at(self, path: impl Into<PathBuf>) -> MeshAt {
        MeshAt {
            path: path.into(),
            error: self,
        }
    }
}

impl Fault for MeshError {
    fn what(&self, lang: Lang) -> String {
        let what = self.fault.what(lang);
        match (self.line, lang) {
            (None, _) => what,
            (Some(n), Lang::En) => format!("line {n}: {what}"),
            (Some(n), Lang::Pt) => format!("linha {n}: {what}"),
        }
    }
    fn fix(&self, lang: Lang) -> String {
        self.fault.fix(lang)
    }
}

/// A mesh's error with the mesh's path before it: `scene/bunny.obj: line 5: …`.
#[derive(Clone, Debug, PartialEq)]
pub struct MeshAt {
    /// The OBJ file.
    pub path: PathBuf,
    /// Its error.
    pub error: MeshError,
}

impl Fault for MeshAt {
    fn what(&self, lang: Lang) -> String {
        format!("{}: {}", self.path.display(), self.error.what(lang))
    }
    fn fix(&self, lang: Lang) -> String {
        self.error.fix(lang)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn a_mesh_s_error_names_its_path_and_line_in_each_language() {
        let e = MeshError::at_line(
            5,
            MeshFault::VertexNotXyz {
                v: Echo::new("v 1 2", 60),
            },
        )
        .at("m/bunny.obj");
        assert_eq!(
            e.what(Lang::En),
            "m/bunny.obj: line 5: the vertex \"v 1 2\" is not `v x y z` (three numbers)"
        );
        assert_eq!(
            e.what(Lang::Pt),
            "m/bunny.obj: linha 5: o vértice \"v 1 2\" não é `v x y z` (três números)"
        );
        assert_eq!(e.fix(Lang::Pt), "escreva cada vértice como `v x y z`");
        let e = MeshError::of(MeshFault::Degenerate {
            k: 3,
            object: Object(Some("ear".into())),
            precision: "f32".into(),
        });
        assert_eq!(
            e.what(Lang::En),
            "the face's triangle 3 (object \"ear\") is degenerate in f32: its corners lie on one \
             line"
        );
        assert_eq!(
            e.what(Lang::Pt),
            "o triângulo 3 (objeto \"ear\") da face é degenerado em f32: seus vértices estão \
             numa reta"
        );
        let f = MeshFault::CornerNotFinite {
            index: 2,
            precision: "f32".into(),
            or_f64: OrF64(true),
        };
        assert_eq!(
            f.fix(Lang::En),
            "give finite coordinates (or use --precision f64)"
        );
        assert_eq!(
            f.fix(Lang::Pt),
            "dê coordenadas finitas (ou use --precision f64)"
        );
    }
}
