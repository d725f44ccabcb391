//! One colour and line style per model, in every scene, plot and export: the Okabe-Ito palette
//! (distinguishable with every common colour-vision deficiency), with dashes for the models whose
//! curves lie on another's (wave theory on a stiff Sears contact, FE on Sears).

use crate::model::impact::ModelKind;

/// How a model's curve is drawn.
#[derive(Debug, Clone, Copy, PartialEq, Eq)]
pub struct ModelStyle {
    /// sRGB.
    pub rgb: [u8; 3],
    /// Dashed rather than solid.
    pub dashed: bool,
}

/// The style of `model`.
pub const fn model_style(model: ModelKind) -> ModelStyle {
    let (rgb, dashed) = match model {
        ModelKind::Sears => ([213, 94, 0], false),
        ModelKind::Wave => ([0, 114, 178], true),
        ModelKind::LumpedHertz => ([0, 158, 115], false),
        ModelKind::LumpedLinear => ([204, 121, 167], false),
        ModelKind::Kelvin => ([86, 180, 233], false),
        ModelKind::Stereo => ([0, 0, 0], false),
        ModelKind::Fe => ([230, 159, 0], true),
    };
    ModelStyle { rgb, dashed }
}

/// The style of the model a series is named after (`sears`, `lumped-hertz`, ...), if it is one.
pub fn style_of(name: &str) -> Option<ModelStyle> {
    ModelKind::ALL
        .into_iter()
        .find(|m| m.name() == name)
        .map(model_style)
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn every_model_has_its_own_colour() {
        let colours: Vec<[u8; 3]> = ModelKind::ALL.iter().map(|m| model_style(*m).rgb).collect();
        for (i, a) in colours.iter().enumerate() {
            for b in &colours[i + 1..] {
                assert_ne!(a, b);
            }
        }
        assert_eq!(style_of("fe"), Some(model_style(ModelKind::Fe)));
        assert_eq!(style_of("left"), None);
    }
}
