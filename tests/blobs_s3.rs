//! Blobs on an S3-compatible store (moto's server mode, started by `scripts/test`): the blob
//! store's semantics through the real S3 API, and a whole API flow with its blobs there. Skipped
//! with a notice when `CAD2MO_TEST_S3_ENDPOINT` is not set.

use std::sync::Arc;

use cad2mo_server::store::blobs::{sha256_hex, BlobSettings, Blobs};
use cad2mo_tests::app::{zip_dir, TestApp};
use cad2mo_tests::common::workspace_root;
use cad2mo_tests::s3;
use object_store::{ObjectStore, PutPayload};

/// Runs blocking blob calls off the runtime, as the service does.
async fn blocking<T: Send + 'static>(f: impl FnOnce() -> T + Send + 'static) -> T {
    tokio::task::spawn_blocking(f).await.expect("blocking task")
}

#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn put_get_idempotent_corrupt_missing() {
    let Some(place) = s3::place("put_get_idempotent_corrupt_missing").await else { return };
    let dir = tempfile::tempdir().expect("tempdir");
    let blobs = Blobs::open(&place.settings(), dir.path()).await.expect("opens on S3");
    let client = Arc::new(place.client());

    // Round trip, stored under the local folder's layout.
    let bytes: Vec<u8> = (0..200_000u32).flat_map(|i| i.to_le_bytes()).collect();
    let b = blobs.clone();
    let (h, again) = {
        let bytes = bytes.clone();
        blocking(move || (b.put(&bytes).expect("put"), b.get(&sha256_hex(&bytes)).expect("get"))).await
    };
    assert_eq!(h, sha256_hex(&bytes));
    assert_eq!(again.as_deref(), Some(&bytes[..]));
    let meta = client.head(&place.key(&h)).await.expect("the object is where the layout says");
    assert_eq!(meta.size, bytes.len() as u64);
    assert!(!dir.path().join("blobs").exists(), "nothing is written to the local folder");

    // Idempotent: a second put (a second later, so a rewrite would change the object's time)
    // does not write the object again.
    tokio::time::sleep(std::time::Duration::from_millis(1100)).await;
    let b = blobs.clone();
    let bytes2 = bytes.clone();
    assert_eq!(blocking(move || b.put(&bytes2).expect("put again")).await, h);
    let meta2 = client.head(&place.key(&h)).await.expect("still there");
    assert_eq!((meta2.e_tag, meta2.last_modified), (meta.e_tag, meta.last_modified), "the second put rewrote the object");

    // Missing: None, not an error; a name that is no hash: None.
    let b = blobs.clone();
    let (missing, nonsense) = blocking(move || (b.get(&"0".repeat(64)).expect("get"), b.get("../../x").expect("get"))).await;
    assert_eq!((missing, nonsense), (None, None));

    // Listing: this blob only (another object under the prefix is not a blob).
    client.put(&object_store::path::Path::from(format!("{}/README", place.prefix)), PutPayload::from_static(b"x")).await.expect("put");
    let b = blobs.clone();
    assert_eq!(blocking(move || b.list().expect("list")).await, vec![h.clone()]);

    // Overwritten through the S3 API with other bytes: reading is an error, never the bytes.
    let mut tampered = bytes.clone();
    tampered[1000] ^= 1;
    client.put(&place.key(&h), PutPayload::from(tampered)).await.expect("overwrite");
    let b = blobs.clone();
    let h2 = h.clone();
    let e = blocking(move || b.get(&h2)).await.expect_err("a corrupt object is an error");
    assert_eq!(e.kind(), std::io::ErrorKind::InvalidData, "{e}");
}

/// A store that cannot be reached fails at start, with its URL in the message.
#[tokio::test]
async fn unreachable_store_fails_at_open() {
    let Some(place) = s3::place("unreachable_store_fails_at_open").await else { return };
    let dir = tempfile::tempdir().expect("tempdir");
    let settings = BlobSettings { url: Some("s3://no-such-bucket-cad2mo/x".into()), ..place.settings() };
    let e = Blobs::open(&settings, dir.path()).await.expect_err("a missing bucket is refused");
    assert!(e.to_string().contains("s3://no-such-bucket-cad2mo/x"), "{e}");
    let settings = BlobSettings { url: Some("gs://bucket".into()), ..Default::default() };
    assert!(Blobs::open(&settings, dir.path()).await.is_err());
}

/// Upload -> convert -> download with every blob on S3: the bundle, package and report are
/// objects in the bucket, the data folder holds none, and the integrity check is clean.
#[tokio::test(flavor = "multi_thread", worker_threads = 2)]
async fn api_flow_with_blobs_on_s3() {
    let Some(place) = s3::place("api_flow_with_blobs_on_s3").await else { return };
    let settings = place.settings();
    let app = TestApp::spawn_with(|s| s.blobs = settings).await;
    let bundle = zip_dir(&workspace_root().join("tests/in/pendulum"));
    let (model_id, version, job_id) = app.upload_model_ok(bundle.clone(), &[]).await;
    let job = app.wait_for_job(&job_id).await;
    assert_eq!(job["status"], "succeeded", "{job:#}");
    let r = app.package(&model_id, version).await;
    assert_eq!(r.status(), 200);
    let zip = r.bytes().await.expect("bytes");
    let names: Vec<String> =
        zip::ZipArchive::new(std::io::Cursor::new(zip.to_vec())).expect("zip").file_names().map(String::from).collect();
    assert!(names.iter().any(|n| n == "PENDULUM/Mechanics.mo"), "{names:?}");
    let r = app.bundle(&model_id, version).await;
    assert_eq!(r.bytes().await.expect("bytes").to_vec(), bundle, "the bundle round-trips");

    // The three blobs are objects in the bucket under the prefix, none in the data folder.
    let client = place.client();
    for h in [sha256_hex(&bundle), sha256_hex(&zip)] {
        client.head(&place.key(&h)).await.unwrap_or_else(|e| panic!("{h} is not in the bucket: {e}"));
    }
    let local = app.data_dir().join("blobs");
    assert!(!local.exists() || std::fs::read_dir(&local).expect("dir").next().is_none(), "blobs were written locally");

    let store = cad2mo_server::store::Store::open(&format!("sqlite://{}", app.data_dir().join("cad2mo.db").display())).await.expect("db");
    let blobs = Blobs::open(&place.settings(), app.data_dir()).await.expect("blobs");
    let report = cad2mo_server::store::integrity::check(&store, &blobs).await.expect("check");
    assert!(report.is_consistent() && report.orphans.is_empty(), "{report:?}");
    assert_eq!(report.stored, 3, "{report:?}");

    // A package corrupted in the bucket is refused (500), never served.
    client.put(&place.key(&sha256_hex(&zip)), PutPayload::from(vec![0u8; zip.len()])).await.expect("overwrite");
    let r = app.package(&model_id, version).await;
    assert_eq!(r.status(), 500);
    let body = r.bytes().await.expect("body");
    assert!(!body.starts_with(&[0, 0, 0, 0]), "corrupt bytes were served");
}
