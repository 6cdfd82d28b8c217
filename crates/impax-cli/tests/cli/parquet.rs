//! `impax sweep --format parquet` (feature `parquet`): the file holds exactly the CSV's rows,
//! nulls where the CSV cells are empty, across several row groups.

use crate::support::impax;

use parquet::file::reader::{FileReader, SerializedFileReader};
use parquet::record::RowAccessor;

#[test]
fn parquet_rows_equal_csv_rows() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-parquet-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let path = dir.join("sweep.parquet");
    // 201 × 201 points × 3 laws = 121 203 rows: two row groups of at least 65 536 rows.
    let grid = [
        "sweep",
        "--grid",
        "alpha-deg=0:90:201",
        "--grid",
        "spin-ratio=-3:3:201",
        "--law",
        "whittaker,brach,energetic",
        "--quiet",
    ];
    let csv = impax().args(grid).output().unwrap();
    assert!(csv.status.success());
    let csv = String::from_utf8(csv.stdout).unwrap();
    let mut args = grid.to_vec();
    let p = path.to_str().unwrap();
    args.extend(["--format", "parquet", "--out", p]);
    let out = impax().args(&args).output().unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );

    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    assert!(reader.metadata().num_row_groups() >= 2);
    let mut lines = csv.lines();
    let header: Vec<&str> = lines.next().unwrap().split(',').collect();
    let schema = reader.metadata().file_metadata().schema_descr();
    let names: Vec<String> = (0..schema.num_columns())
        .map(|i| schema.column(i).name().to_string())
        .collect();
    assert_eq!(names, header);
    let mut n = 0;
    for (row, line) in reader.get_row_iter(None).unwrap().zip(lines) {
        let row = row.unwrap();
        for (i, cell) in line.split(',').enumerate() {
            match header[i] {
                "law" | "status" | "sequence" => assert_eq!(row.get_string(i).unwrap(), cell),
                _ => match row.get_double(i) {
                    Ok(x) => assert_eq!(x.to_bits(), cell.parse::<f64>().unwrap().to_bits()),
                    Err(_) => assert!(cell.is_empty(), "null for `{cell}`"),
                },
            }
        }
        n += 1;
    }
    assert_eq!(n, 201 * 201 * 3);
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn invalid_points_are_nulls() {
    let dir = std::path::Path::new(env!("CARGO_TARGET_TMPDIR"))
        .join(format!("impax-parquet-null-{}", std::process::id()));
    std::fs::create_dir_all(&dir).unwrap();
    let scenario = dir.join("rigid.toml");
    std::fs::write(
        &scenario,
        "friction = 0.3\nrestitution = 0.5\n[body]\nshape = \"rigid\"\nmass = 1\ninertia = 0.5\ncontact = [0.2, -1.0]\nvelocity = [0.5, -1.0]\n",
    )
    .unwrap();
    let path = dir.join("s.parquet");
    let out = impax()
        .args([
            "sweep",
            scenario.to_str().unwrap(),
            "--grid",
            "vy=-1:0:3",
            "--law",
            "energetic",
            "--columns",
            "p_n,energy_ratio",
            "--format",
            "parquet",
            "--out",
            path.to_str().unwrap(),
            "--quiet",
        ])
        .output()
        .unwrap();
    assert!(
        out.status.success(),
        "{}",
        String::from_utf8_lossy(&out.stderr)
    );
    let reader = SerializedFileReader::new(std::fs::File::open(&path).unwrap()).unwrap();
    let rows: Vec<_> = reader
        .get_row_iter(None)
        .unwrap()
        .map(|r| r.unwrap())
        .collect();
    assert_eq!(rows.len(), 3);
    assert!(rows[0].get_double(4).unwrap() > 0.0); // p_n
    assert_eq!(rows[2].get_string(2).unwrap(), "invalid");
    assert!(rows[2].get_double(4).is_err()); // null
    let _ = std::fs::remove_dir_all(&dir);
}

#[test]
fn parquet_needs_an_output_file() {
    let out = impax()
        .args(["sweep", "--grid", "alpha-deg=0:1:3", "--format", "parquet"])
        .output()
        .unwrap();
    assert_eq!(out.status.code(), Some(2));
    assert!(String::from_utf8_lossy(&out.stderr).contains("--out"));
}
