//! `impax map` and `impax compare --plot`: the files exist, decode as PNG / parse as SVG,
//! have the requested size and are not blank; the map's Whittaker boundary for the sphere
//! matches paper A's eq. 13 threshold to grid resolution; bad map input exits with 2.

use crate::support::{bad, run_ok};

use std::path::PathBuf;

/// A fresh directory for this test's files (removed on drop).
struct Dir(PathBuf);
impl Dir {
    fn new(name: &str) -> Self {
        let d = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
            .join(format!("impax-plots-{}-{name}", std::process::id()));
        std::fs::create_dir_all(&d).unwrap();
        Dir(d)
    }
    fn file(&self, name: &str) -> String {
        self.0.join(name).to_str().unwrap().to_string()
    }
}
impl Drop for Dir {
    fn drop(&mut self) {
        let _ = std::fs::remove_dir_all(&self.0);
    }
}

/// The PNG decodes, has the size, and is a picture: many colours, much non-white ink, and
/// dark text-like pixels.
fn check_png(path: &str, size: (u32, u32)) {
    let img = image::open(path)
        .unwrap_or_else(|e| panic!("{path} does not decode as PNG: {e}"))
        .to_rgb8();
    assert_eq!(img.dimensions(), size, "{path}");
    let mut colours = std::collections::HashSet::new();
    let (mut ink, mut dark) = (0usize, 0usize);
    for p in img.pixels() {
        colours.insert(p.0);
        if p.0 != [255, 255, 255] {
            ink += 1;
        }
        if p.0.iter().all(|&c| c < 60) {
            dark += 1;
        }
    }
    let total = (size.0 * size.1) as usize;
    assert!(colours.len() > 20, "{path}: only {} colours", colours.len());
    assert!(
        ink > total / 10,
        "{path}: almost blank ({ink} of {total} pixels)"
    );
    assert!(
        dark > total / 500,
        "{path}: no text or axes ({dark} dark pixels)"
    );
}

/// The SVG parses, has the size, text (labels) and drawing elements.
fn check_svg(path: &str, size: (u32, u32), raster: bool) {
    let text = std::fs::read_to_string(path).unwrap();
    let doc = roxmltree::Document::parse(&text)
        .unwrap_or_else(|e| panic!("{path} does not parse as SVG: {e}"));
    let root = doc.root_element();
    assert_eq!(root.tag_name().name(), "svg");
    assert_eq!(root.attribute("width"), Some(size.0.to_string().as_str()));
    assert_eq!(root.attribute("height"), Some(size.1.to_string().as_str()));
    let count = |tag: &str| {
        doc.descendants()
            .filter(|n| n.tag_name().name() == tag)
            .count()
    };
    assert!(
        count("text") > 10,
        "{path}: {} text elements",
        count("text")
    );
    assert!(
        count("polyline") + count("path") + count("line") > 5,
        "{path}: no lines"
    );
    if raster {
        assert!(count("image") >= 1, "{path}: no raster image");
    }
}

#[test]
fn seed_map_png_and_svg_with_the_eq13_boundary() {
    let d = Dir::new("map");
    let png = d.file("map.png");
    let report = run_ok(&[
        "map",
        "--grid",
        "alpha-deg=0:89:90",
        "--grid",
        "spin-ratio=-3:3:601",
        "--law",
        "whittaker,energetic",
        "--out",
        &png,
        "--size",
        "900x500",
        "--quiet",
    ]);
    check_png(&png, (900, 500));
    // The boundary found on the grid lies within half a γ step (0.005) of eq. 13.
    assert!(report.contains("within half a grid step: yes"), "{report}");
    let worst: Vec<f64> = report
        .split("max |engine − eq. 13| = ")
        .nth(1)
        .unwrap()
        .split([' ', ','])
        .filter_map(|w| w.parse().ok())
        .take(1)
        .collect();
    assert!(worst[0] <= 0.005 + 1e-12, "{report}");
    assert!(
        report.contains("γ*₊ = 0.205811, γ*₋ = -1.205811"),
        "{report}"
    );
    let svg = d.file("map.svg");
    run_ok(&[
        "map",
        "--grid",
        "alpha-deg=0:89:90",
        "--grid",
        "spin-ratio=-3:3:121",
        "--law",
        "whittaker",
        "--out",
        &svg,
        "--quiet",
    ]);
    check_svg(&svg, (1050, 720), true);
}

#[test]
fn sequence_and_scalar_maps() {
    let d = Dir::new("kinds");
    let seq = d.file("seq.png");
    run_ok(&[
        "map",
        "--grid",
        "friction=0:1:41",
        "--grid",
        "restitution=0:1:21",
        "--what",
        "sequence",
        "--law",
        "newton,brach",
        "--out",
        &seq,
        "--size",
        "800x400",
        "--quiet",
    ]);
    check_png(&seq, (800, 400));
    let scalar = d.file("ratio.svg");
    run_ok(&[
        "map",
        "--grid",
        "alpha-deg=0:80:41",
        "--grid",
        "spin-ratio=-2:2:41",
        "--what",
        "energy_ratio",
        "--out",
        &scalar,
        "--size",
        "1200x700",
        "--quiet",
    ]);
    check_svg(&scalar, (1200, 700), true);
}

#[test]
fn compare_plot_draws_routh_and_energy_bars() {
    let d = Dir::new("routh");
    for (name, svg) in [("r.png", false), ("r.svg", true)] {
        let f = d.file(name);
        let table = run_ok(&["compare", "--plot", &f]);
        assert!(table.contains("whittaker"), "the table is still printed");
        if svg {
            check_svg(&f, (1500, 900), false);
            let text = std::fs::read_to_string(&f).unwrap();
            for label in [
                "line of sticking",
                "line of maximum compression",
                "energetic",
            ] {
                assert!(text.contains(label), "{f} lacks `{label}`");
            }
        } else {
            check_png(&f, (1500, 900));
        }
    }
}

#[test]
fn bad_map_input_exits_2() {
    // Run where a stray file would be seen; none of these may create one.
    let d = Dir::new("bad");
    let x = d.file("x.png");
    let g = ["--grid", "alpha-deg=0:80:5", "--grid", "spin-ratio=-1:1:5"];
    let with = |extra: &[&'static str]| {
        let mut v = vec!["map"];
        v.extend_from_slice(&g);
        v.extend_from_slice(extra);
        v
    };
    let with_out = |extra: &[&str]| {
        let mut v = with(&[]);
        v.push("--out");
        v.push(&x);
        v.extend_from_slice(extra);
        v.iter().map(|s| s.to_string()).collect::<Vec<String>>()
    };
    fn refs(v: &[String]) -> Vec<&str> {
        v.iter().map(String::as_str).collect()
    }
    bad(&refs(&with_out(&["--what", "colour"])), "colour");
    bad(&refs(&with_out(&["--what", "status"])), "status");
    bad(&refs(&with_out(&["--size", "10x10"])), "--size");
    bad(&with(&["--out", "x.jpg"]), ".png or .svg");
    bad(&with(&["--out", "/nonexistent/dir/x.png"]), "cannot create");
    bad(&with(&[]), "--out");
    bad(
        &["map", "--grid", "alpha-deg=0:80:5", "--out", "x.png"],
        "two grid axes",
    );
    bad(
        &[
            "map",
            "--random",
            "friction=0:1",
            "--samples",
            "9",
            "--out",
            "x.png",
        ],
        "needs a grid",
    );
    bad(&["compare", "--plot", "x.gif"], ".png or .svg");
}
