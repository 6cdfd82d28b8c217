//! The URDF reader: coordinates in tree order, fixed joints merged by the parallel-axis
//! theorem (checked against the same robot with those joints made prismatic and held at
//! zero), origins and inertial frames rotated by roll–pitch–yaw, merged links still
//! addressable, mimic joints flagged, and every refusal naming its URDF element.

use super::multibody_models::*;
use impax::math::{Mat3, SplitMix64, Vec3};
use impax::multibody::{crba, read_urdf, ContactSpec, JointKind, Model, UrdfOptions, Workspace};
use nalgebra::{DMatrix, Rotation3};

fn err(text: &str, options: &UrdfOptions) -> String {
    read_urdf(text, options).unwrap_err().to_string()
}

#[test]
fn multibody_urdf_solo12_coordinates() {
    let fixed = solo12(false);
    assert_eq!((fixed.nq(), fixed.nv()), (12, 12));
    let legs = ["FL", "FR", "HL", "HR"];
    let names: Vec<String> = legs
        .iter()
        .flat_map(|l| ["HAA", "HFE", "KFE"].map(|j| format!("{l}_{j}")))
        .collect();
    assert_eq!(fixed.coordinates(), names.as_slice());
    let floating = solo12(true);
    assert_eq!((floating.nq(), floating.nv()), (19, 18));
    assert_eq!(
        &floating.coordinates()[..7],
        ["x", "y", "z", "qw", "qx", "qy", "qz"]
    );
    assert_eq!(
        &floating.speeds()[..6],
        ["vx", "vy", "vz", "wx", "wy", "wz"]
    );
    assert_eq!(&floating.coordinates()[7..], names.as_slice());
    assert_eq!(floating.joints()[0].kind, JointKind::Free);
    // 13 bodies: the base and 12 leg links (the feet merged into the lower legs).
    assert_eq!(floating.bodies().len(), 13);
    let ur5 = ur5();
    assert_eq!(
        ur5.coordinates(),
        [
            "shoulder_pan_joint",
            "shoulder_lift_joint",
            "elbow_joint",
            "wrist_1_joint",
            "wrist_2_joint",
            "wrist_3_joint"
        ]
    );
}

/// The total mass is the sum of the file's `<mass value>`s.
#[test]
fn multibody_urdf_total_mass_is_kept() {
    for (text, model) in [(SOLO12, solo12(true)), (UR5, ur5())] {
        let file: f64 = text
            .split("<mass value=\"")
            .skip(1)
            .map(|s| s[..s.find('"').unwrap()].parse::<f64>().unwrap())
            .sum();
        let model_mass: f64 = model.bodies().iter().map(|b| b.mass).sum();
        assert!(
            (file - model_mass).abs() < 1e-14 * file,
            "{file} vs {model_mass}"
        );
    }
}

/// Merging a fixed joint equals keeping it as a prismatic joint held at zero: the mass
/// matrix of the other coordinates, every contact's position and Jacobian agree.
fn check_merge(text: &str, fixed_joint_names: &[&str], contacts: &[&str], floating: bool) -> f64 {
    let mut unmerged = text.to_string();
    for name in fixed_joint_names {
        let tag = format!("<joint name=\"{name}\" type=\"fixed\">");
        assert!(unmerged.contains(&tag), "{tag}");
        unmerged = unmerged.replace(&tag, &format!("<joint name=\"{name}\" type=\"prismatic\">"));
    }
    let mut options = UrdfOptions::default().floating_base(floating);
    for c in contacts {
        options = options.contact(ContactSpec::parse(c).unwrap());
    }
    let a = read_urdf(text, &options).unwrap().model;
    let b = read_urdf(&unmerged, &options).unwrap().model;
    let keep: Vec<usize> = (0..b.nv())
        .filter(|&i| !fixed_joint_names.contains(&b.speeds()[i].as_str()))
        .collect();
    let keep_q: Vec<usize> = (0..b.nq())
        .filter(|&i| !fixed_joint_names.contains(&b.coordinates()[i].as_str()))
        .collect();
    assert_eq!(keep.len(), a.nv());
    let mut rng = SplitMix64(3);
    let (mut wa, mut wb) = (Workspace::new(&a), Workspace::new(&b));
    let mut worst: f64 = 0.0;
    for _ in 0..20 {
        let (qa, _) = random_state(&a, &mut rng);
        let mut qb = vec![0.0; b.nq()];
        for (i, &k) in keep_q.iter().enumerate() {
            qb[k] = qa[i];
        }
        wa.update(&a, &qa).unwrap();
        wb.update(&b, &qb).unwrap();
        let ma = crba(&a, &mut wa).clone();
        let mb = crba(&b, &mut wb).select_rows(&keep).select_columns(&keep);
        worst = worst.max(relative_error(&ma, &mb));
        for k in 0..a.contacts().len() {
            let ja = impax::multibody::contact_jacobian(&a, &wa, k).unwrap();
            let jb = impax::multibody::contact_jacobian(&b, &wb, k)
                .unwrap()
                .select_columns(&keep);
            let ja = DMatrix::from_fn(3, a.nv(), |i, j| ja[(i, j)]);
            worst = worst.max(relative_error(
                &ja,
                &DMatrix::from_fn(3, a.nv(), |i, j| jb[(i, j)]),
            ));
            let pa = impax::multibody::contact_position(&a, wa.poses(), k);
            let pb = impax::multibody::contact_position(&b, wb.poses(), k);
            worst = worst.max((0..3).map(|i| (pa[i] - pb[i]).abs()).fold(0.0, f64::max));
        }
    }
    worst
}

#[test]
fn multibody_urdf_fixed_joints_merge_by_the_parallel_axis_theorem() {
    let ankles = ["FL_ANKLE", "FR_ANKLE", "HL_ANKLE", "HR_ANKLE"];
    let solo = check_merge(SOLO12, &ankles, &FEET, true);
    assert!(solo < 1e-12, "solo12: {solo:e}");
    // A heavy merged link with a rotated fixed origin and a rotated inertial frame.
    let text = r#"<robot name="t">
      <link name="a"><inertial><origin xyz="0.1 0 0" rpy="0.2 0 0"/><mass value="2"/>
        <inertia ixx="0.3" ixy="0.01" ixz="0" iyy="0.2" iyz="0.02" izz="0.1"/></inertial></link>
      <link name="b"><inertial><origin xyz="0.3 -0.2 0.1" rpy="0.4 -0.7 1.1"/><mass value="1.5"/>
        <inertia ixx="0.05" ixy="0.001" ixz="0.002" iyy="0.07" iyz="0.003" izz="0.02"/></inertial></link>
      <link name="c"><inertial><origin xyz="0 0 -0.4" rpy="0 0.3 0"/><mass value="3"/>
        <inertia ixx="0.2" ixy="0" ixz="0" iyy="0.25" iyz="0" izz="0.05"/></inertial></link>
      <link name="d"><inertial><origin xyz="0 0.1 0" rpy="1 2 3"/><mass value="0.5"/>
        <inertia ixx="0.01" ixy="0" ixz="0" iyy="0.02" iyz="0" izz="0.015"/></inertial></link>
      <joint name="j1" type="revolute"><parent link="a"/><child link="b"/>
        <origin xyz="0.2 0.1 0" rpy="0.1 0.2 0.3"/><axis xyz="0 1 0"/></joint>
      <joint name="weld" type="fixed"><parent link="b"/><child link="c"/>
        <origin xyz="0.5 0 -0.1" rpy="-0.6 0.9 0.2"/></joint>
      <joint name="j2" type="continuous"><parent link="c"/><child link="d"/>
        <origin xyz="0 0.3 -0.2" rpy="0.3 0 0.5"/><axis xyz="1 0 1"/></joint>
    </robot>"#;
    let hand = check_merge(text, &["weld"], &["c:0.1,0.2,-0.3", "d:0,0,-0.2"], true);
    assert!(hand < 1e-12, "hand: {hand:e}");
    println!("merged vs prismatic held at zero: worst relative error solo12 {solo:.2e}, hand-written {hand:.2e}");
}

/// Roll–pitch–yaw is `Rz(y) Ry(p) Rx(r)` (nalgebra's `from_euler_angles`), for joint origins
/// and for inertial frames.
#[test]
fn multibody_urdf_rpy_convention() {
    let (r, p, y) = (0.3, -0.8, 1.9);
    let text = format!(
        r#"<robot name="t"><link name="a"/>
      <link name="b"><inertial><origin xyz="0 0 0" rpy="{r} {p} {y}"/><mass value="1"/>
        <inertia ixx="1" ixy="0" ixz="0" iyy="2" iyz="0" izz="3"/></inertial></link>
      <joint name="j" type="revolute"><parent link="a"/><child link="b"/>
        <origin xyz="1 2 3" rpy="{r} {p} {y}"/><axis xyz="0 0 1"/></joint></robot>"#
    );
    let robot = read_urdf(&text, &UrdfOptions::default()).unwrap();
    let rot = Rotation3::from_euler_angles(r, p, y).into_inner();
    let joint = &robot.model.joints()[1];
    assert!((joint.placement.rotation - rot).amax() < 1e-15);
    assert_eq!(joint.placement.translation, Vec3::new(1.0, 2.0, 3.0));
    let inertia = robot.model.bodies()[1].inertia;
    let expected = rot * Mat3::from_diagonal(&Vec3::new(1.0, 2.0, 3.0)) * rot.transpose();
    assert!((inertia - expected).amax() < 1e-15);
}

#[test]
fn multibody_urdf_merged_links_stay_addressable() {
    let robot = read_urdf(SOLO12, &UrdfOptions::default().floating_base(true)).unwrap();
    let foot = robot.link("FL_FOOT").unwrap();
    let leg = robot.link("FL_LOWER_LEG").unwrap();
    assert_eq!(foot.body, leg.body);
    assert_eq!(robot.model.bodies()[foot.body].name, "FL_LOWER_LEG");
    // FL_ANKLE's origin: xyz="0 0.008 -0.16".
    assert!((foot.placement.translation - Vec3::new(0.0, 0.008, -0.16)).amax() < 1e-15);
    assert_eq!(robot.links.len(), 17);
    assert!(robot.mimic_joints.is_empty());
}

const ARM: &str = r#"<robot name="arm">
  <link name="base"/>
  <link name="rod"><inertial><origin xyz="0 0 -0.5"/><mass value="2"/>
    <inertia ixx="0.1" ixy="0" ixz="0" iyy="0.1" iyz="0" izz="0.01"/></inertial></link>
  <link name="finger"><inertial><origin xyz="0 0 -0.1"/><mass value="0.1"/>
    <inertia ixx="0.001" ixy="0" ixz="0" iyy="0.001" iyz="0" izz="0.0001"/></inertial></link>
  <joint name="pin" type="revolute"><parent link="base"/><child link="rod"/>
    <axis xyz="0 1 0"/></joint>
  <joint name="grip" type="revolute"><parent link="rod"/><child link="finger"/>
    <origin xyz="0 0 -1"/><axis xyz="0 1 0"/><mimic joint="pin" multiplier="2" offset="0.1"/></joint>
</robot>"#;

#[test]
fn multibody_urdf_mimic_joints_are_independent_and_flagged() {
    let robot = read_urdf(ARM, &UrdfOptions::default()).unwrap();
    assert_eq!(robot.model.coordinates(), ["pin", "grip"]);
    assert_eq!(robot.mimic_joints.len(), 1);
    let m = &robot.mimic_joints[0];
    assert_eq!(
        (
            m.joint.as_str(),
            m.mimicked.as_str(),
            m.multiplier,
            m.offset
        ),
        ("grip", "pin", 2.0, 0.1)
    );
    let bad = ARM.replace("<mimic joint=\"pin\"", "<mimic joint=\"nope\"");
    assert_eq!(
        err(&bad, &UrdfOptions::default()),
        "urdf: joint \"grip\": mimics an unknown joint \"nope\""
    );
}

#[test]
fn multibody_urdf_refusals_name_the_element() {
    let o = UrdfOptions::default();
    let bad = SOLO12.replacen("<parent link=\"FL_UPPER_LEG\"/>", "<parent link=\"x\"/>", 1);
    assert_eq!(
        err(&bad, &o),
        "urdf: joint \"FL_KFE\": unknown parent link \"x\""
    );
    let bad = SOLO12.replace(
        "<joint name=\"FL_HAA\" type=\"revolute\">",
        "<joint name=\"FL_HAA\" type=\"floating\">",
    );
    assert!(
        err(&bad, &o).starts_with("urdf: joint \"FL_HAA\": a floating joint is not supported"),
        "{}",
        err(&bad, &o)
    );
    let bad = SOLO12.replace(
        "<joint name=\"FL_HAA\" type=\"revolute\">",
        "<joint name=\"FL_HAA\" type=\"planar\">",
    );
    assert!(err(&bad, &o).starts_with("urdf: joint \"FL_HAA\": a planar joint is not supported"));
    let bad = ARM.replace(
        "<axis xyz=\"0 1 0\"/></joint>\n  <joint",
        "<axis xyz=\"0 0 0\"/></joint>\n  <joint",
    );
    assert_eq!(
        err(&bad, &o),
        "urdf: joint \"pin\": axis: must be a nonzero direction, got (0, 0, 0)"
    );
    // A closed loop: the finger is also the child of a second joint.
    let bad = ARM.replace(
        "</robot>",
        "<joint name=\"loop\" type=\"fixed\"><parent link=\"base\"/><child link=\"finger\"/></joint></robot>",
    );
    assert_eq!(
        err(&bad, &o),
        "urdf: joint \"loop\": link \"finger\" is already the child of joint \"grip\" (a closed loop is not a tree)"
    );
    let bad = ARM.replace(
        "<link name=\"base\"/>",
        "<link name=\"base\"/><link name=\"stray\"/>",
    );
    assert_eq!(
        err(&bad, &o),
        "urdf: the links: several root links (base, stray): the tree must be connected"
    );
    let bad = ARM.replace("<mass value=\"2\"/>", "<mass value=\"-2\"/>");
    assert_eq!(
        err(&bad, &o),
        "urdf: link \"rod\": the mass must be a finite number ≥ 0, got -2"
    );
    let bad = ARM.replace("ixx=\"0.1\" ixy=\"0\"", "ixx=\"0.1\" ixy=\"0.5\"");
    assert!(
        err(&bad, &o).starts_with("urdf: link \"rod\": inertia: must be positive semidefinite"),
        "{}",
        err(&bad, &o)
    );
    assert!(err("<robot name=\"x\"><link", &o).starts_with("urdf: the XML: cannot be read"));
    // An unexpanded xacro stub (example-robot-data's ur3.urdf): no link at all.
    assert_eq!(
        err("<robot name=\"ur3\"></robot>", &o),
        "urdf: the links: the robot has no <link> (an empty description, e.g. a xacro file not expanded)"
    );
    let c = UrdfOptions::default().contact(ContactSpec::new("nowhere"));
    assert_eq!(err(ARM, &c), "contact[nowhere]: unknown link \"nowhere\"");
}

/// A link without inertial data has no mass: fine when welded on or when it carries
/// something, refused (naming its coordinate) when it is a moving massless leaf.
#[test]
fn multibody_urdf_massless_links() {
    let o = UrdfOptions::default();
    let welded = ARM.replace("</robot>", "<link name=\"sensor\"/><joint name=\"s\" type=\"fixed\"><parent link=\"rod\"/><child link=\"sensor\"/></joint></robot>");
    assert!(read_urdf(&welded, &o).is_ok());
    let leaf = ARM.replace("</robot>", "<link name=\"sensor\"/><joint name=\"spin\" type=\"continuous\"><parent link=\"rod\"/><child link=\"sensor\"/></joint></robot>");
    let e = err(&leaf, &o);
    assert!(
        e.starts_with("urdf: the mass matrix at the neutral configuration: mass matrix: must be positive definite, but the coordinate spin (speed 2) moves no mass"),
        "{e}"
    );
}

#[test]
fn multibody_urdf_contact_specs() {
    let c = ContactSpec::parse("FL_FOOT").unwrap();
    assert_eq!((c.link.as_str(), c.point), ("FL_FOOT", Vec3::zeros()));
    let c: ContactSpec = "HR_LOWER_LEG:0, 0.008,-0.16".parse().unwrap();
    assert_eq!(c.point, Vec3::new(0.0, 0.008, -0.16));
    assert_eq!(c.name, "HR_LOWER_LEG:0, 0.008,-0.16");
    for bad in ["", ":1,2,3", "FOOT:1,2", "FOOT:1,2,x", "FOOT:1,2,inf"] {
        let e = ContactSpec::parse(bad).unwrap_err();
        assert_eq!(e.field(), "contact", "{bad}");
    }
    // A point on a merged link's frame is where the unmerged link puts it.
    let options = UrdfOptions::default()
        .floating_base(true)
        .contact(ContactSpec::new("FL_FOOT"))
        .contact("FL_LOWER_LEG:0,0.008,-0.16".parse().unwrap());
    let model: Model = read_urdf(SOLO12, &options).unwrap().model;
    let (a, b) = (&model.contacts()[0], &model.contacts()[1]);
    assert_eq!(a.body, b.body);
    assert!((a.point - b.point).amax() < 1e-16);
}
