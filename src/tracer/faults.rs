//! What can stop a pixel from being explained, and what would fix it, in English and
//! Portuguese (crate::text, [`crate::faults!`]).

use crate::faults;

faults! {
    /// Why a pixel's ray tree cannot be explained.
    pub enum TracerFault {
        /// A reflection ray's contribution O_r·C_r is not finite; `material` is
        /// ` (material "glass")` or nothing.
        ReflectedOverflows { level: u32, precision: &'static str, material: String } =>
            "the colour this pixel's ray of level {level} adds, O_r·C_r (Eq. 4.17), overflows \
             {precision}{material}",
            "a cor que o raio de nível {level} deste pixel soma, O_r·C_r (Eq. 4.17), passa do \
             alcance de {precision}{material}";
            fix "bring the reflectivity O_r and the colours into a smaller range (a reflectivity \
                 lies in [0, 1])",
                "use uma reflexividade O_r e cores de ordem de grandeza menor (uma reflexividade \
                 fica em [0, 1])";
        /// A transmission ray's contribution O_t·C_t is not finite.
        TransmittedOverflows { level: u32, precision: &'static str, material: String } =>
            "the colour this pixel's ray of level {level} adds, O_t·C_t (Section 4.4), \
             overflows {precision}{material}",
            "a cor que o raio de nível {level} deste pixel soma, O_t·C_t (Seção 4.4), passa do \
             alcance de {precision}{material}";
            fix "bring the transmissivity O_t and the colours into a smaller range (a \
                 transmissivity lies in [0, 1])",
                "use uma transmissividade O_t e cores de ordem de grandeza menor (uma \
                 transmissividade fica em [0, 1])";
    }
}
