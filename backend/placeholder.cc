void mdlc_backend_placeholder(){}
