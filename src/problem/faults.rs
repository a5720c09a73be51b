//! What can be wrong with a problem file and what would fix it, in English and Portuguese: the
//! faults of validation ([`super::validate`]), as values (crate::text, [`crate::faults!`]).

use crate::faults;

faults! {
    /// What the problem asks for: a point, a ray or a scene.
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
    }
}
