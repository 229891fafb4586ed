<!DOCTYPE qgis PUBLIC 'http://mrcc.com/qgis.dtd' 'SYSTEM'>
<qgis minScale="100000000" labelsEnabled="0" version="3.22.16-Białowieża" maxScale="0" simplifyLocal="1" styleCategories="Symbology|Labeling|Fields|Forms|MapTips|AttributeTable|Rendering" simplifyDrawingTol="1" simplifyDrawingHints="1" simplifyAlgorithm="0" simplifyMaxScale="1" hasScaleBasedVisibilityFlag="0" symbologyReferenceScale="-1">
  <renderer-v2 symbollevels="0" type="categorizedSymbol" referencescale="-1" forceraster="0" attr="polarity" enableorderby="0">
    <categories>
      <category label="Warm by day" value="hot" render="true" symbol="0"/>
      <category label="Cool by day" value="cold" render="true" symbol="1"/>
    </categories>
    <symbols>
      <symbol type="fill" alpha="1" name="0" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" pass="0" locked="0">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" type="QString" name="border_width_map_unit_scale"/>
            <Option value="0,0,0,0" type="QString" name="color"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="215,48,39,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.5" type="QString" name="outline_width"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="no" type="QString" name="style"/>
          </Option>
          <prop k="border_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="color" v="0,0,0,0"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="215,48,39,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.5"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="style" v="no"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
      <symbol type="fill" alpha="1" name="1" force_rhr="0" clip_to_extent="1">
        <data_defined_properties>
          <Option type="Map">
            <Option value="" type="QString" name="name"/>
            <Option name="properties"/>
            <Option value="collection" type="QString" name="type"/>
          </Option>
        </data_defined_properties>
        <layer enabled="1" class="SimpleFill" pass="0" locked="0">
          <Option type="Map">
            <Option value="3x:0,0,0,0,0,0" type="QString" name="border_width_map_unit_scale"/>
            <Option value="0,0,0,0" type="QString" name="color"/>
            <Option value="bevel" type="QString" name="joinstyle"/>
            <Option value="0,0" type="QString" name="offset"/>
            <Option value="3x:0,0,0,0,0,0" type="QString" name="offset_map_unit_scale"/>
            <Option value="MM" type="QString" name="offset_unit"/>
            <Option value="69,117,180,255" type="QString" name="outline_color"/>
            <Option value="solid" type="QString" name="outline_style"/>
            <Option value="0.5" type="QString" name="outline_width"/>
            <Option value="MM" type="QString" name="outline_width_unit"/>
            <Option value="no" type="QString" name="style"/>
          </Option>
          <prop k="border_width_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="color" v="0,0,0,0"/>
          <prop k="joinstyle" v="bevel"/>
          <prop k="offset" v="0,0"/>
          <prop k="offset_map_unit_scale" v="3x:0,0,0,0,0,0"/>
          <prop k="offset_unit" v="MM"/>
          <prop k="outline_color" v="69,117,180,255"/>
          <prop k="outline_style" v="solid"/>
          <prop k="outline_width" v="0.5"/>
          <prop k="outline_width_unit" v="MM"/>
          <prop k="style" v="no"/>
          <data_defined_properties>
            <Option type="Map">
              <Option value="" type="QString" name="name"/>
              <Option name="properties"/>
              <Option value="collection" type="QString" name="type"/>
            </Option>
          </data_defined_properties>
        </layer>
      </symbol>
    </symbols>
    <rotation/>
    <sizescale/>
  </renderer-v2>
  <blendMode>0</blendMode>
  <featureBlendMode>0</featureBlendMode>
  <layerOpacity>1</layerOpacity>
  <fieldConfiguration>
    <field name="anomaly_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="x" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="y" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lat" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="lon" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="7" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="area_m2" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diameter_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="circularity" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth_sigma_m" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="3" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity_sigma_m2s" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="status" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="polarity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="class_cue" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="p_mine" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="priority" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="set_aside_reason" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="n_scans" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_day_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="contrast_night_k" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_r" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="mine_curve_level" configurationFlags="None">
      <editWidget type="Range">
        <config>
          <Option type="Map">
            <Option value="true" type="bool" name="AllowNull"/>
            <Option value="1e+09" type="double" name="Max"/>
            <Option value="-1e+09" type="double" name="Min"/>
            <Option value="2" type="int" name="Precision"/>
            <Option value="1" type="int" name="Step"/>
            <Option value="SpinBox" type="QString" name="Style"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="fix_quality" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="figure" configurationFlags="None">
      <editWidget type="">
        <config>
          <Option/>
        </config>
      </editWidget>
    </field>
    <field name="contrast_series" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="short_id" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="depth" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="diffusivity" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="likelihood" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
    <field name="cue_confidence_pct" configurationFlags="None">
      <editWidget type="TextEdit">
        <config>
          <Option type="Map">
            <Option value="false" type="bool" name="IsMultiline"/>
            <Option value="false" type="bool" name="UseHtml"/>
          </Option>
        </config>
      </editWidget>
    </field>
  </fieldConfiguration>
  <aliases>
    <alias field="anomaly_id" index="0" name="Suspect id"/>
    <alias field="x" index="1" name="Easting (m, survey UTM)"/>
    <alias field="y" index="2" name="Northing (m, survey UTM)"/>
    <alias field="lat" index="3" name="Latitude (°, WGS84)"/>
    <alias field="lon" index="4" name="Longitude (°, WGS84)"/>
    <alias field="area_m2" index="5" name="Area (m²)"/>
    <alias field="diameter_m" index="6" name="Diameter (m)"/>
    <alias field="circularity" index="7" name="Circularity (0-1)"/>
    <alias field="depth_m" index="8" name="Burial depth (m)"/>
    <alias field="depth_sigma_m" index="9" name="Depth uncertainty, 1σ (m)"/>
    <alias field="diffusivity_m2s" index="10" name="Thermal diffusivity (m²/s)"/>
    <alias field="diffusivity_sigma_m2s" index="11" name="Diffusivity uncertainty, 1σ (m²/s)"/>
    <alias field="status" index="12" name="Characterisation status"/>
    <alias field="polarity" index="13" name="Polarity"/>
    <alias field="class_cue" index="14" name="Class cue"/>
    <alias field="cue_confidence" index="15" name="Class cue confidence (0-1)"/>
    <alias field="p_mine" index="16" name="Mine likelihood (0-1)"/>
    <alias field="priority" index="17" name="Priority (1 = first)"/>
    <alias field="set_aside_reason" index="18" name="Set aside because"/>
    <alias field="n_scans" index="19" name="Scans seen"/>
    <alias field="contrast_day_k" index="20" name="Day contrast (K)"/>
    <alias field="contrast_night_k" index="21" name="Night contrast (K)"/>
    <alias field="mine_curve_r" index="22" name="Match with a mine's diurnal curve (-1 to 1)"/>
    <alias field="mine_curve_level" index="23" name="Offset from a mine's diurnal curve (swings)"/>
    <alias field="fix_quality" index="24" name="GNSS fix quality"/>
    <alias field="figure" index="25" name="Contrast curve"/>
    <alias field="contrast_series" index="26" name="Contrast series (JSON)"/>
    <alias field="short_id" index="27" name="Short id"/>
    <alias field="depth" index="28" name="Burial depth ± 1σ"/>
    <alias field="diffusivity" index="29" name="Thermal diffusivity ± 1σ"/>
    <alias field="likelihood" index="30" name="Mine likelihood"/>
    <alias field="cue_confidence_pct" index="31" name="Class cue confidence"/>
  </aliases>
  <defaults>
    <default field="anomaly_id" applyOnUpdate="0" expression=""/>
    <default field="x" applyOnUpdate="0" expression=""/>
    <default field="y" applyOnUpdate="0" expression=""/>
    <default field="lat" applyOnUpdate="0" expression=""/>
    <default field="lon" applyOnUpdate="0" expression=""/>
    <default field="area_m2" applyOnUpdate="0" expression=""/>
    <default field="diameter_m" applyOnUpdate="0" expression=""/>
    <default field="circularity" applyOnUpdate="0" expression=""/>
    <default field="depth_m" applyOnUpdate="0" expression=""/>
    <default field="depth_sigma_m" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_m2s" applyOnUpdate="0" expression=""/>
    <default field="diffusivity_sigma_m2s" applyOnUpdate="0" expression=""/>
    <default field="status" applyOnUpdate="0" expression=""/>
    <default field="polarity" applyOnUpdate="0" expression=""/>
    <default field="class_cue" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence" applyOnUpdate="0" expression=""/>
    <default field="p_mine" applyOnUpdate="0" expression=""/>
    <default field="priority" applyOnUpdate="0" expression=""/>
    <default field="set_aside_reason" applyOnUpdate="0" expression=""/>
    <default field="n_scans" applyOnUpdate="0" expression=""/>
    <default field="contrast_day_k" applyOnUpdate="0" expression=""/>
    <default field="contrast_night_k" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_r" applyOnUpdate="0" expression=""/>
    <default field="mine_curve_level" applyOnUpdate="0" expression=""/>
    <default field="fix_quality" applyOnUpdate="0" expression=""/>
    <default field="figure" applyOnUpdate="0" expression=""/>
    <default field="contrast_series" applyOnUpdate="0" expression=""/>
    <default field="short_id" applyOnUpdate="0" expression=""/>
    <default field="depth" applyOnUpdate="0" expression=""/>
    <default field="diffusivity" applyOnUpdate="0" expression=""/>
    <default field="likelihood" applyOnUpdate="0" expression=""/>
    <default field="cue_confidence_pct" applyOnUpdate="0" expression=""/>
  </defaults>
  <constraints>
    <constraint field="anomaly_id" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="x" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="y" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="lat" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="lon" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="area_m2" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diameter_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="circularity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth_sigma_m" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity_m2s" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity_sigma_m2s" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="status" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="polarity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="class_cue" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="cue_confidence" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="p_mine" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="priority" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="set_aside_reason" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="n_scans" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_day_k" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_night_k" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="mine_curve_r" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="mine_curve_level" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="fix_quality" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="figure" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="contrast_series" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="short_id" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="depth" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="diffusivity" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="likelihood" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
    <constraint field="cue_confidence_pct" exp_strength="0" constraints="0" notnull_strength="0" unique_strength="0"/>
  </constraints>
  <constraintExpressions>
    <constraint field="anomaly_id" desc="" exp=""/>
    <constraint field="x" desc="" exp=""/>
    <constraint field="y" desc="" exp=""/>
    <constraint field="lat" desc="" exp=""/>
    <constraint field="lon" desc="" exp=""/>
    <constraint field="area_m2" desc="" exp=""/>
    <constraint field="diameter_m" desc="" exp=""/>
    <constraint field="circularity" desc="" exp=""/>
    <constraint field="depth_m" desc="" exp=""/>
    <constraint field="depth_sigma_m" desc="" exp=""/>
    <constraint field="diffusivity_m2s" desc="" exp=""/>
    <constraint field="diffusivity_sigma_m2s" desc="" exp=""/>
    <constraint field="status" desc="" exp=""/>
    <constraint field="polarity" desc="" exp=""/>
    <constraint field="class_cue" desc="" exp=""/>
    <constraint field="cue_confidence" desc="" exp=""/>
    <constraint field="p_mine" desc="" exp=""/>
    <constraint field="priority" desc="" exp=""/>
    <constraint field="set_aside_reason" desc="" exp=""/>
    <constraint field="n_scans" desc="" exp=""/>
    <constraint field="contrast_day_k" desc="" exp=""/>
    <constraint field="contrast_night_k" desc="" exp=""/>
    <constraint field="mine_curve_r" desc="" exp=""/>
    <constraint field="mine_curve_level" desc="" exp=""/>
    <constraint field="fix_quality" desc="" exp=""/>
    <constraint field="figure" desc="" exp=""/>
    <constraint field="contrast_series" desc="" exp=""/>
    <constraint field="short_id" desc="" exp=""/>
    <constraint field="depth" desc="" exp=""/>
    <constraint field="diffusivity" desc="" exp=""/>
    <constraint field="likelihood" desc="" exp=""/>
    <constraint field="cue_confidence_pct" desc="" exp=""/>
  </constraintExpressions>
  <expressionfields>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="short_id" comment="" subType="0" precision="0" expression="'S-' || lpad(to_string(to_int(regexp_substr(&quot;anomaly_id&quot;, '(\\d+)$'))), 3, '0')" length="0"/>
    <field type="10" typeName="" name="depth" comment="" subType="0" precision="0" expression="CASE WHEN &quot;depth_m&quot; * 100 IS NULL THEN 'not characterised' WHEN &quot;depth_sigma_m&quot; * 100 IS NULL THEN format_number(&quot;depth_m&quot; * 100, 1) || ' cm' ELSE format_number(&quot;depth_m&quot; * 100, 1) || ' ± ' || format_number(&quot;depth_sigma_m&quot; * 100, 1) || ' cm' END" length="0"/>
    <field type="10" typeName="" name="diffusivity" comment="" subType="0" precision="0" expression="CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 IS NULL THEN 'not characterised' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 > &quot;diffusivity_m2s&quot; * 1e6 THEN 'unconstrained' WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 IS NULL THEN CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' mm²/s' ELSE CASE WHEN &quot;diffusivity_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_m2s&quot; * 1e6))))) END || ' ± ' || CASE WHEN &quot;diffusivity_sigma_m2s&quot; * 1e6 = 0 THEN '0' ELSE format_number(round(&quot;diffusivity_sigma_m2s&quot; * 1e6, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6)))), max(0, 1 - floor(log10(abs(&quot;diffusivity_sigma_m2s&quot; * 1e6))))) END || ' mm²/s' END" length="0"/>
    <field type="10" typeName="" name="likelihood" comment="" subType="0" precision="0" expression="CASE WHEN attribute('p_mine') IS NULL THEN 'not estimated' ELSE format_number(100 * attribute('p_mine'), 0) || ' %' END" length="0"/>
    <field type="10" typeName="" name="cue_confidence_pct" comment="" subType="0" precision="0" expression="CASE WHEN coalesce(attribute('cue_confidence'), attribute('confidence')) IS NULL THEN NULL ELSE format_number(100 * coalesce(attribute('cue_confidence'), attribute('confidence')), 0) || ' %' END" length="0"/>
  </expressionfields>
  <attributetableconfig actionWidgetStyle="dropDown" sortExpression="coalesce(attribute('priority'), 1000000 * (CASE WHEN &quot;class_cue&quot; = 'at_mine' THEN 0 WHEN &quot;class_cue&quot; = 'ap_mine' THEN 1 WHEN &quot;class_cue&quot; = 'unknown' THEN 2 ELSE 3 END) - round(1000 * max(abs(&quot;contrast_day_k&quot;), abs(&quot;contrast_night_k&quot;))))" sortOrder="0">
    <columns>
      <column type="field" hidden="0" name="anomaly_id" width="-1"/>
      <column type="field" hidden="0" name="polarity" width="-1"/>
      <column type="field" hidden="0" name="area_m2" width="-1"/>
      <column type="field" hidden="0" name="p_mine" width="-1"/>
      <column type="field" hidden="0" name="priority" width="-1"/>
      <column type="field" hidden="0" name="cue_confidence" width="-1"/>
      <column type="field" hidden="0" name="set_aside_reason" width="-1"/>
      <column type="field" hidden="0" name="short_id" width="-1"/>
      <column type="field" hidden="0" name="depth" width="-1"/>
      <column type="field" hidden="0" name="diffusivity" width="-1"/>
      <column type="field" hidden="0" name="likelihood" width="-1"/>
      <column type="field" hidden="0" name="cue_confidence_pct" width="-1"/>
      <column type="actions" hidden="1" width="-1"/>
    </columns>
  </attributetableconfig>
  <conditionalstyles>
    <rowstyles/>
    <fieldstyles/>
  </conditionalstyles>
  <storedexpressions/>
  <editform tolerant="1"></editform>
  <editforminit/>
  <editforminitcodesource>0</editforminitcodesource>
  <editforminitfilepath></editforminitfilepath>
  <editforminitcode><![CDATA[]]></editforminitcode>
  <featformsuppress>0</featformsuppress>
  <editorlayout>tablayout</editorlayout>
  <attributeEditorForm>
    <attributeEditorContainer name="Suspect" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Identification" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="27" name="short_id" showLabel="1"/>
        <attributeEditorField index="0" name="anomaly_id" showLabel="1"/>
        <attributeEditorField index="17" name="priority" showLabel="1"/>
        <attributeEditorField index="14" name="class_cue" showLabel="1"/>
        <attributeEditorField index="30" name="likelihood" showLabel="1"/>
        <attributeEditorField index="31" name="cue_confidence_pct" showLabel="1"/>
        <attributeEditorField index="12" name="status" showLabel="1"/>
        <attributeEditorField index="13" name="polarity" showLabel="1"/>
        <attributeEditorField index="18" name="set_aside_reason" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Burial depth and soil" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="28" name="depth" showLabel="1"/>
        <attributeEditorField index="29" name="diffusivity" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Thermal contrast" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="20" name="contrast_day_k" showLabel="1"/>
        <attributeEditorField index="21" name="contrast_night_k" showLabel="1"/>
        <attributeEditorField index="22" name="mine_curve_r" showLabel="1"/>
        <attributeEditorField index="23" name="mine_curve_level" showLabel="1"/>
        <attributeEditorField index="19" name="n_scans" showLabel="1"/>
      </attributeEditorContainer>
      <attributeEditorContainer name="Shape" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="6" name="diameter_m" showLabel="1"/>
        <attributeEditorField index="5" name="area_m2" showLabel="1"/>
        <attributeEditorField index="7" name="circularity" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Contrast curve" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Contrast curve" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="25" name="figure" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Position" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Position" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="1" name="x" showLabel="1"/>
        <attributeEditorField index="2" name="y" showLabel="1"/>
        <attributeEditorField index="3" name="lat" showLabel="1"/>
        <attributeEditorField index="4" name="lon" showLabel="1"/>
        <attributeEditorField index="24" name="fix_quality" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
    <attributeEditorContainer name="Stored values" columnCount="1" showLabel="1" groupBox="0" visibilityExpressionEnabled="0" visibilityExpression="">
      <attributeEditorContainer name="Stored values" columnCount="1" showLabel="1" groupBox="1" visibilityExpressionEnabled="0" visibilityExpression="">
        <attributeEditorField index="8" name="depth_m" showLabel="1"/>
        <attributeEditorField index="9" name="depth_sigma_m" showLabel="1"/>
        <attributeEditorField index="10" name="diffusivity_m2s" showLabel="1"/>
        <attributeEditorField index="11" name="diffusivity_sigma_m2s" showLabel="1"/>
        <attributeEditorField index="16" name="p_mine" showLabel="1"/>
        <attributeEditorField index="15" name="cue_confidence" showLabel="1"/>
        <attributeEditorField index="26" name="contrast_series" showLabel="1"/>
      </attributeEditorContainer>
    </attributeEditorContainer>
  </attributeEditorForm>
  <editable/>
  <labelOnTop/>
  <reuseLastValue/>
  <dataDefinedFieldProperties/>
  <widgets/>
  <mapTip>&lt;b>[% "short_id" %]&lt;/b> [% "class_cue" %] ([% "status" %])&lt;br/>depth [% "depth" %]&lt;br/>diffusivity [% "diffusivity" %]</mapTip>
  <layerGeometryType>2</layerGeometryType>
</qgis>
