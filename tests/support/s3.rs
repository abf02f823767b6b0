//! The S3-compatible test server (`scripts/test` starts moto's server mode and exports
//! `CAD2MO_TEST_S3_ENDPOINT`): a bucket per test binary, a fresh prefix per test, and the
//! settings that put a service's blobs there.

use std::sync::atomic::{AtomicUsize, Ordering};

use cad2mo_server::store::blobs::BlobSettings;

/// The bucket the tests use (created on first use; moto accepts any credentials).
pub const BUCKET: &str = "cad2mo-test";
/// Credentials and region for the test server (moto does not check them).
pub const ACCESS_KEY_ID: &str = "test";
pub const SECRET_ACCESS_KEY: &str = "test";
pub const REGION: &str = "us-east-1";

/// A place on the test server: endpoint, bucket and a prefix no other test uses.
#[derive(Clone, Debug)]
pub struct S3Place {
    pub endpoint: String,
    pub bucket: String,
    pub prefix: String,
}

impl S3Place {
    /// `s3://bucket/prefix`.
    pub fn url(&self) -> String {
        format!("s3://{}/{}", self.bucket, self.prefix)
    }

    /// Blob settings for a service storing here.
    pub fn settings(&self) -> BlobSettings {
        BlobSettings {
            url: Some(self.url()),
            s3_endpoint: Some(self.endpoint.clone()),
            s3_access_key_id: Some(ACCESS_KEY_ID.into()),
            s3_secret_access_key: Some(SECRET_ACCESS_KEY.into()),
            s3_region: Some(REGION.into()),
        }
    }

    /// Environment of a `cad2mo serve` process storing here.
    pub fn env(&self) -> Vec<(&'static str, String)> {
        vec![
            ("CAD2MO_BLOB_URL", self.url()),
            ("CAD2MO_S3_ENDPOINT", self.endpoint.clone()),
            ("AWS_ACCESS_KEY_ID", ACCESS_KEY_ID.into()),
            ("AWS_SECRET_ACCESS_KEY", SECRET_ACCESS_KEY.into()),
            ("AWS_REGION", REGION.into()),
        ]
    }

    /// A client of the bucket through the S3 API, independent of the service's blob store (to
    /// look at or tamper with objects).
    pub fn client(&self) -> object_store::aws::AmazonS3 {
        object_store::aws::AmazonS3Builder::new()
            .with_endpoint(&self.endpoint)
            .with_allow_http(true)
            .with_bucket_name(&self.bucket)
            .with_access_key_id(ACCESS_KEY_ID)
            .with_secret_access_key(SECRET_ACCESS_KEY)
            .with_region(REGION)
            .build()
            .expect("S3 client")
    }

    /// The key of a blob: the local folder's layout under the prefix.
    pub fn key(&self, hash: &str) -> object_store::path::Path {
        object_store::path::Path::from(format!("{}/{}/{hash}", self.prefix, &hash[..2]))
    }
}

/// The test server with a fresh prefix, the bucket created; `None` with a printed notice when
/// `CAD2MO_TEST_S3_ENDPOINT` is not set (a failure when tools are required, as `scripts/test`
/// starts the server).
pub async fn place(test: &str) -> Option<S3Place> {
    let place = try_place(test).await;
    if place.is_none() {
        println!("NOTICE: {test} skipped: no S3-compatible test server (set CAD2MO_TEST_S3_ENDPOINT; scripts/test starts moto)");
    }
    place
}

/// [`place`] without the notice (for tests that fall back to something else).
pub async fn try_place(test: &str) -> Option<S3Place> {
    let Some(endpoint) = std::env::var("CAD2MO_TEST_S3_ENDPOINT").ok().filter(|e| !e.is_empty()) else {
        assert!(
            !crate::common::tools_required(),
            "{test}: CAD2MO_TEST_S3_ENDPOINT is not set but tools are required (scripts/test starts moto)"
        );
        return None;
    };
    let endpoint = endpoint.trim_end_matches('/').to_string();
    // CreateBucket: moto takes it unsigned; 200 when new, 409 when this or another test made it.
    let created = reqwest::Client::new().put(format!("{endpoint}/{BUCKET}")).send().await.expect("S3 test server answers");
    assert!(created.status().is_success() || created.status() == 409, "creating the bucket: {}", created.status());
    static N: AtomicUsize = AtomicUsize::new(0);
    let nanos = std::time::SystemTime::now().duration_since(std::time::UNIX_EPOCH).map(|d| d.as_nanos()).unwrap_or(0);
    let prefix = format!("{test}-{}-{nanos}-{}", std::process::id(), N.fetch_add(1, Ordering::Relaxed));
    Some(S3Place { endpoint, bucket: BUCKET.into(), prefix })
}
