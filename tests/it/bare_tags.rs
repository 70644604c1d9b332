//! A tagged variant whose fields all have defaults may be written as its
//! bare tag (issue 38.8): `contact: rigid` is `contact: {type: rigid}`
//! (it was refused once `rigid` gained its optional `restitution`); a
//! variant with a required field still needs its mapping, and says so.

use crate::support::{Scratch, manifest_dir, text, vbi};

const SCENE: &str = "\
name: bare-tags
bridge: {type: beam, spans: [25.0], bending_stiffness: 8.323e9, mass_per_length: 2303.0}
vehicles:
  - {type: oscillator, sprung_mass: 5750, unsprung_mass: 575, stiffness: 1.595e6, damping: 0, speed: 20}
contact: {type: rigid}
";

/// The resolved scene of `source`, as its Debug text (every f64 at
/// round-trip precision).
fn resolved(source: &str) -> String {
    let loaded = vbi::plan::load_str(source, "bare.yaml").unwrap_or_else(|e| panic!("{e}"));
    format!("{:?}", loaded.scenario)
}

#[test]
fn a_bare_tag_is_the_variant_with_every_field_at_its_default() {
    let mapping = resolved(SCENE);
    assert!(mapping.contains("Rigid"), "{mapping}");
    assert_eq!(
        resolved(&SCENE.replace("contact: {type: rigid}", "contact: rigid")),
        mapping
    );
    // A unit variant, as before.
    assert_eq!(
        resolved(&SCENE.replace("contact: {type: rigid}", "contact: permanent")),
        resolved(&SCENE.replace("contact: {type: rigid}", "contact: {type: permanent}"))
    );
    // And on a surface.
    assert_eq!(
        resolved(&SCENE.replace("contact: {type: rigid}", "surface: smooth")),
        resolved(&SCENE.replace("contact: {type: rigid}", "surface: {type: smooth}"))
    );
}

#[test]
fn a_bare_tag_of_a_variant_with_required_fields_says_to_write_the_mapping() {
    let scratch = Scratch::new("bare_tags", "required");
    let path = scratch.path("scene.yaml");
    std::fs::write(
        &path,
        SCENE.replace(
            "contact: {type: rigid}",
            "surface: harmonic\ncontact: rigdi",
        ),
    )
    .unwrap();
    let out = vbi(&["check".as_ref(), path.as_os_str()], manifest_dir());
    let stderr = text(&out.stderr);
    assert_eq!(out.status.code(), Some(2), "{stderr}");
    let file = path.display().to_string();
    for (head, message) in [
        (
            format!("error: {file}:5:10: "),
            "`harmonic` is a variant with fields: write it as a mapping with `type: harmonic` \
             and its fields",
        ),
        (format!("error: {file}:6:10: "), "unknown variant `rigdi`"),
    ] {
        assert!(
            stderr
                .lines()
                .any(|l| l.starts_with(&head) && l.contains(message)),
            "no `{head}{message}` in\n{stderr}"
        );
    }
    assert!(stderr.contains("= help: did you mean `rigid`?"), "{stderr}");
    assert!(!stderr.contains("panicked"), "{stderr}");
}
