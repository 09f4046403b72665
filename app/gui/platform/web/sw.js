// The browser build's service worker (registered by index.html when served): the page keeps
// working without a network once it has been visited. Every file is asked of the network first
// (a new build shows at once) and kept; when the network fails, the kept copy answers.
'use strict';
const CACHE = 'collision-sandbox';
const FILES = ['./', 'index.html', 'sandbox.js', 'sandbox.wasm', 'sandbox.data'];

self.addEventListener('install', (event) => {
  event.waitUntil(caches.open(CACHE).then((cache) => cache.addAll(FILES))
    .then(() => self.skipWaiting()));
});

self.addEventListener('activate', (event) => event.waitUntil(self.clients.claim()));

self.addEventListener('fetch', (event) => {
  const request = event.request;
  if (request.method !== 'GET' || new URL(request.url).origin !== self.location.origin) return;
  event.respondWith(fetch(request).then((response) => {
    if (response.ok) {
      const copy = response.clone();
      caches.open(CACHE).then((cache) => cache.put(request, copy));
    }
    return response;
  }).catch(() => caches.match(request, { ignoreSearch: true }).then((kept) => {
    if (kept) return kept;
    throw new Error('offline, and ' + request.url + ' was never kept');
  })));
});
