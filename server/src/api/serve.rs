//! The listener: connections, not routes. Replaces `axum::serve` so that no client can hold the
//! service's sockets or file descriptors without bound (issue 26, point 7):
//!
//! - at most `max_connections` connections are served at once (the start-up lowers it below the
//!   file-descriptor limit, see [`raise_fd_limit`]);
//! - beyond that, [`RESERVE`] more are served one request each, answering only `/api/health`
//!   (anything else is a quick 503 `busy` naming the limit); when those are full too, the oldest
//!   is dropped for the newest, so a health probe always gets in however many idle sockets a
//!   client opens;
//! - a request's head must arrive within `header_timeout` (hyper's clock, which also runs while a
//!   kept-alive connection waits for its next request; for HTTP/2, which hyper does not time,
//!   our watchdog closes a connection that has no request in flight and has begun none for
//!   `header_timeout`, however many frames (pings, settings, a never-ending header block) it
//!   sends), a body may pause at most `body_timeout`
//!   between two pieces (`tower_http`'s `RequestBodyTimeout`: a stalled upload is dropped), and a
//!   connection with no request in flight and no byte either way for `keep_alive` is closed.

use std::collections::VecDeque;
use std::future::Future;
use std::io;
use std::pin::Pin;
use std::sync::atomic::{AtomicU64, AtomicUsize, Ordering};
use std::sync::Arc;
use std::task::{Context, Poll};
use std::time::{Duration, Instant};

use axum::body::Body;
use axum::http::{Request, Response};
use axum::Router;
use hyper::body::Incoming;
use hyper_util::rt::{TokioExecutor, TokioIo, TokioTimer};
use hyper_util::server::conn::auto::Builder;
use tokio::io::{AsyncRead, AsyncWrite, ReadBuf};
use tokio::net::{TcpListener, TcpStream};
use tokio::sync::{OwnedSemaphorePermit, Semaphore};
use tokio::task::{AbortHandle, JoinSet};
use tower::ServiceExt;

use super::ApiError;

/// Connections beyond `max_connections` served for health probes (one request each).
pub const RESERVE: usize = 16;
/// Descriptors kept free for everything but HTTP connections (database pool, blob files, the
/// live-view socket, the reserve, log files): `max_connections` stays this far below the limit.
pub const FD_MARGIN: u64 = 256;
/// How long a reserve connection may take to send its request head.
const RESERVE_HEADER_TIMEOUT: Duration = Duration::from_secs(1);
/// How long connections may finish their requests after a stop is asked for.
const SHUTDOWN_GRACE: Duration = Duration::from_secs(10);

/// The connection limits (from `Settings`).
#[derive(Clone, Copy, Debug)]
pub struct Limits {
    pub max_connections: usize,
    pub header_timeout: Duration,
    pub body_timeout: Duration,
    pub keep_alive: Duration,
}

/// Raises the soft limit on open files to the hard limit where the system allows it, and returns
/// the soft limit in force (`None` where there is no such limit or it cannot be read).
pub fn raise_fd_limit() -> Option<u64> {
    #[cfg(unix)]
    {
        match rlimit::increase_nofile_limit(u64::MAX) {
            Ok(n) => Some(n),
            Err(e) => {
                tracing::warn!(error = %e, "could not raise the open-file limit");
                rlimit::Resource::NOFILE.get().ok().map(|(soft, _)| soft)
            }
        }
    }
    #[cfg(not(unix))]
    {
        None
    }
}

/// `wanted` connections, lowered to fit under the open-file limit `fd_limit` (with
/// [`FD_MARGIN`] and [`RESERVE`] left over); at least 1.
pub fn connection_cap(wanted: usize, fd_limit: Option<u64>) -> usize {
    let fit = fd_limit.map_or(usize::MAX, |n| usize::try_from(n.saturating_sub(FD_MARGIN + RESERVE as u64)).unwrap_or(usize::MAX));
    wanted.min(fit).max(1)
}

/// Serves `router` on `listener` within `limits` until `shutdown` resolves; then lets
/// connections finish for up to 10 s and drops the rest.
pub async fn serve(listener: TcpListener, router: Router, limits: Limits, shutdown: impl Future<Output = ()>) -> io::Result<()> {
    let router = router.layer(tower_http::timeout::RequestBodyTimeoutLayer::new(limits.body_timeout));
    let mut full = Builder::new(TokioExecutor::new());
    full.http1().timer(TokioTimer::new()).header_read_timeout(limits.header_timeout);
    full.http2().timer(TokioTimer::new());
    let full = Arc::new(full);
    let mut reserve = Builder::new(TokioExecutor::new());
    reserve.http1().timer(TokioTimer::new()).header_read_timeout(RESERVE_HEADER_TIMEOUT.min(limits.header_timeout)).keep_alive(false);
    reserve.http2().timer(TokioTimer::new());
    let reserve = Arc::new(reserve);

    let slots = Arc::new(Semaphore::new(limits.max_connections.max(1)));
    let (stop_tx, stop_rx) = tokio::sync::watch::channel(false);
    let mut conns = JoinSet::new();
    let mut reserved: VecDeque<AbortHandle> = VecDeque::new();
    let mut last_error_log: Option<Instant> = None;
    tokio::pin!(shutdown);
    loop {
        while conns.try_join_next().is_some() {}
        let accepted = tokio::select! {
            a = listener.accept() => a,
            () = &mut shutdown => break,
        };
        let stream = match accepted {
            Ok((stream, _)) => stream,
            Err(e) => {
                // Out of descriptors (or a connection reset before accept): wait a little rather
                // than spin; log at most once a second.
                if last_error_log.is_none_or(|t| t.elapsed() >= Duration::from_secs(1)) {
                    tracing::warn!(error = %e, "accept error");
                    last_error_log = Some(Instant::now());
                }
                tokio::time::sleep(Duration::from_millis(20)).await;
                continue;
            }
        };
        let _ = stream.set_nodelay(true);
        match slots.clone().try_acquire_owned() {
            Ok(permit) => {
                let conn = Conn::new(stream, Some(permit));
                conns.spawn(run(conn, full.clone(), router.clone(), limits, stop_rx.clone(), Mode::Full));
            }
            Err(_) => {
                reserved.retain(|h| !h.is_finished());
                if reserved.len() >= RESERVE {
                    if let Some(oldest) = reserved.pop_front() {
                        oldest.abort();
                    }
                }
                let conn = Conn::new(stream, None);
                let mode = Mode::Reserve { limit: limits.max_connections };
                reserved.push_back(conns.spawn(run(conn, reserve.clone(), router.clone(), limits, stop_rx.clone(), mode)));
            }
        }
    }
    let _ = stop_tx.send(true);
    let _ = tokio::time::timeout(SHUTDOWN_GRACE, async { while conns.join_next().await.is_some() {} }).await;
    Ok(())
}

#[derive(Clone, Copy)]
enum Mode {
    /// Every route.
    Full,
    /// Over the connection cap: health only.
    Reserve { limit: usize },
}

/// One connection: served until it ends, is idle for `keep_alive`, or the service stops.
async fn run(
    conn: Conn,
    builder: Arc<Builder<TokioExecutor>>,
    router: Router,
    limits: Limits,
    mut stop: tokio::sync::watch::Receiver<bool>,
    mode: Mode,
) {
    let activity = conn.activity.clone();
    let service = {
        let activity = activity.clone();
        hyper::service::service_fn(move |req: Request<Incoming>| {
            let router = router.clone();
            let busy = InFlight::enter(activity.clone());
            async move {
                let resp = match mode {
                    Mode::Reserve { limit } if req.uri().path() != "/api/health" => over_limit(limit),
                    _ => router.oneshot(req.map(Body::new)).await.unwrap_or_else(|e| match e {}),
                };
                drop(busy);
                Ok::<_, std::convert::Infallible>(resp)
            }
        })
    };
    let served = builder.serve_connection_with_upgrades(TokioIo::new(conn), service);
    tokio::pin!(served);
    let header_timeout = match mode {
        Mode::Full => limits.header_timeout,
        Mode::Reserve { .. } => RESERVE_HEADER_TIMEOUT.min(limits.header_timeout),
    };
    let tick = (limits.keep_alive.min(header_timeout) / 4).clamp(Duration::from_millis(20), Duration::from_secs(1));
    let mut ticks = tokio::time::interval(tick);
    let mut closing: Option<Instant> = None;
    loop {
        tokio::select! {
            _ = served.as_mut() => return,
            _ = ticks.tick() => {
                // No byte either way for `keep_alive`, or (HTTP/2 above all: hyper times HTTP/1
                // heads itself) no request begun for `header_timeout` while none is in flight.
                let idle = activity.in_flight() == 0
                    && (activity.idle_for() >= limits.keep_alive || activity.since_request() >= header_timeout);
                match closing {
                    None if idle => {
                        served.as_mut().graceful_shutdown();
                        closing = Some(Instant::now());
                    }
                    // Asked to close and still open with nothing in flight: drop it.
                    Some(t) if activity.in_flight() == 0 && t.elapsed() >= Duration::from_secs(1) => return,
                    _ => {}
                }
            }
            r = stop.changed(), if closing.is_none() => {
                if r.is_ok() {
                    served.as_mut().graceful_shutdown();
                    closing = Some(Instant::now());
                }
            }
        }
    }
}

/// 503 for a request over the connection cap (health excepted).
fn over_limit(limit: usize) -> Response<Body> {
    axum::response::IntoResponse::into_response(ApiError::TooManyConnections { limit })
}

/// When a connection last moved a byte, and how many of its requests are being answered.
struct Activity {
    start: Instant,
    last_ms: AtomicU64,
    /// When a request last began or ended (ms since `start`; 0: none yet).
    request_ms: AtomicU64,
    in_flight: AtomicUsize,
}

impl Activity {
    fn touch(&self) {
        let ms = u64::try_from(self.start.elapsed().as_millis()).unwrap_or(u64::MAX);
        self.last_ms.store(ms, Ordering::Relaxed);
    }

    fn touch_request(&self) {
        let ms = u64::try_from(self.start.elapsed().as_millis()).unwrap_or(u64::MAX);
        self.request_ms.store(ms, Ordering::Relaxed);
    }

    /// Since a request last began or ended (or the connection was opened).
    fn since_request(&self) -> Duration {
        self.start.elapsed().saturating_sub(Duration::from_millis(self.request_ms.load(Ordering::Relaxed)))
    }

    fn idle_for(&self) -> Duration {
        self.start.elapsed().saturating_sub(Duration::from_millis(self.last_ms.load(Ordering::Relaxed)))
    }

    fn in_flight(&self) -> usize {
        self.in_flight.load(Ordering::Relaxed)
    }
}

/// A request being answered (its response's head not yet handed to hyper).
struct InFlight(Arc<Activity>);

impl InFlight {
    fn enter(a: Arc<Activity>) -> InFlight {
        a.in_flight.fetch_add(1, Ordering::Relaxed);
        a.touch_request();
        InFlight(a)
    }
}

impl Drop for InFlight {
    fn drop(&mut self) {
        self.0.touch();
        self.0.touch_request();
        self.0.in_flight.fetch_sub(1, Ordering::Relaxed);
    }
}

/// A TCP connection that notes its activity and holds its slot until the socket is closed (also
/// after a WebSocket upgrade, which takes the socket over).
struct Conn {
    stream: TcpStream,
    activity: Arc<Activity>,
    _slot: Option<OwnedSemaphorePermit>,
}

impl Conn {
    fn new(stream: TcpStream, slot: Option<OwnedSemaphorePermit>) -> Conn {
        let activity = Arc::new(Activity {
            start: Instant::now(),
            last_ms: AtomicU64::new(0),
            request_ms: AtomicU64::new(0),
            in_flight: AtomicUsize::new(0),
        });
        Conn { stream, activity, _slot: slot }
    }
}

impl AsyncRead for Conn {
    fn poll_read(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &mut ReadBuf<'_>) -> Poll<io::Result<()>> {
        let before = buf.filled().len();
        let r = Pin::new(&mut self.stream).poll_read(cx, buf);
        if matches!(r, Poll::Ready(Ok(()))) && buf.filled().len() > before {
            self.activity.touch();
        }
        r
    }
}

impl AsyncWrite for Conn {
    fn poll_write(mut self: Pin<&mut Self>, cx: &mut Context<'_>, buf: &[u8]) -> Poll<io::Result<usize>> {
        let r = Pin::new(&mut self.stream).poll_write(cx, buf);
        if matches!(r, Poll::Ready(Ok(n)) if n > 0) {
            self.activity.touch();
        }
        r
    }

    fn poll_write_vectored(mut self: Pin<&mut Self>, cx: &mut Context<'_>, bufs: &[io::IoSlice<'_>]) -> Poll<io::Result<usize>> {
        let r = Pin::new(&mut self.stream).poll_write_vectored(cx, bufs);
        if matches!(r, Poll::Ready(Ok(n)) if n > 0) {
            self.activity.touch();
        }
        r
    }

    fn is_write_vectored(&self) -> bool {
        self.stream.is_write_vectored()
    }

    fn poll_flush(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.stream).poll_flush(cx)
    }

    fn poll_shutdown(mut self: Pin<&mut Self>, cx: &mut Context<'_>) -> Poll<io::Result<()>> {
        Pin::new(&mut self.stream).poll_shutdown(cx)
    }
}

#[cfg(test)]
mod tests {
    use super::*;

    #[test]
    fn cap_stays_below_the_descriptor_limit() {
        assert_eq!(connection_cap(1000, Some(1024)), 1024 - 256 - RESERVE as u64 as usize);
        assert_eq!(connection_cap(1000, Some(65536)), 1000);
        assert_eq!(connection_cap(1000, None), 1000);
        assert_eq!(connection_cap(1000, Some(10)), 1);
    }
}
