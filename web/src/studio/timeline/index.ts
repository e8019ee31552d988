// The growth timeline under the view (issue 45): Play, scrub, speed, loop, range, camera and
// turntable over the plant's growth in time; its bar loads after the first plant (./timeline-bar.ts).
export { LazyTimeline, type TimelineElements } from './lazy-timeline';
export { wireTimeline } from './wire-timeline';
