// For the tests only: an emulated headset (Meta's Immersive Web Emulation Runtime) installed as
// navigator.xr before the page loads, so "Enter VR" can be tried in headless Chromium.
import { XRDevice, metaQuest3 } from "iwer";

const device = new XRDevice(metaQuest3);
device.installRuntime({ forceInstall: true });
window.havenXrDevice = device;
